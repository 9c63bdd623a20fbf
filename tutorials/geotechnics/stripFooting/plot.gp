# Footing pressure against settlement over the ladder (ladder/*/pressure.dat, listed in
# errors.dat), smooth and rough side by side, with Prandtl's (2 + pi) c; and the error of
# q_u against wall time.
set terminal pngcairo size 1200,520 noenhanced
set linetype 8 lc rgb 'brown'   # the eighth run not black, the reference's colour
set output 'pressure.png'
set multiplot layout 1,2
set xlabel 'settlement [mm]'
set ylabel 'footing pressure P / c'
set xrange [0:*]
set yrange [0:9]
set key bottom right spacing 0.85 font ',9'
set arrow from 10, graph 0 to 10, graph 1 nohead dt 3 lc rgb 'gray'
set arrow from 15, graph 0 to 15, graph 1 nohead dt 3 lc rgb 'gray'
do for [w in 'smooth rough'] {
    runs = system("awk '!/^#/ && $2 == \"".w."\" { print $13 }' errors.dat")
    set title sprintf('%s strip footing, B/2 = 0.2 m, weightless Tresca soil (c 26 kPa)', w)
    plot for [r in runs] r.'/pressure.dat' using 1:3 with lines lw 1.5 title r[8:], \
         2 + pi with lines lw 2 lc rgb 'black' title 'Prandtl (2 + pi) c'
}
unset multiplot

set output 'error.png'
set terminal pngcairo size 800,550 noenhanced
unset arrow
set xrange [*:*]
set yrange [*:*]
set logscale x
set xlabel 'wall time [s]'
set ylabel '(q_u - (2 + pi) c) / (2 + pi) c [%]'
set title 'Strip footing on Tresca soil: error of the collapse pressure against run time'
set key top right
series = system("awk '!/^#/ && !seen[$1 \"-\" $2]++ { printf \"%s-%s \", $1, $2 }' errors.dat")
plot for [s in series] sprintf("< awk '$1 \"-\" $2 == \"%s\"' errors.dat", s) using 7:9 \
         with linespoints pt 7 title s, \
     0 with lines lc rgb 'black' notitle
