# Contact pressure under the punch against Sadowsky (the runs of the 10 m model; run='...',
# given by Allrun, is the finest), and the errors of the ladder against run time.
set terminal pngcairo size 900,650 noenhanced
set output 'pressure.png'
set xlabel 'r / a'
set ylabel 'contact pressure p / p_m,  p_m = P / (pi a^2)'
set title 'Rigid smooth circular punch, a = 1 m: mean pressure of the top cells, 10 m model'
set xrange [0:1.6]
set yrange [-0.1:2.5]
set key top left
files = system('ls -d ladder/10-* | sort -t- -k2 -n')
plot run.'/pressure.dat' index 1 using 1:2 with lines lw 2 lc rgb 'black' title 'Sadowsky, P / (2 pi a sqrt(a^2 - r^2))', \
     for [f in files] f.'/pressure.dat' index 0 using 1:2 with linespoints pt 7 \
         title sprintf('h = a / %d', int(f[strstrt(f, '-') + 1:]) / 10)

set output 'error.png'
set xrange [*:*]
set yrange [*:*]
set logscale xy
set xlabel 'wall time [s]'
set ylabel '|error| [%]'
set title 'Rigid circular punch: error against run time'
set key top right
plot for [L in '10 20 40'] 'errors.dat' using ($1 == L ? $5 : NaN):(abs($6)) with linespoints pt 7 lw 2 \
         title 'settlement, '.L.' m model', \
     for [L in '10 20 40'] 'errors.dat' using ($1 == L ? $5 : NaN):7 with linespoints pt 5 dt 2 lw 2 \
         title 'pressure (r <= 0.6 a), '.L.' m model'
