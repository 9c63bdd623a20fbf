# Depth against time on each grid of the ladder, and the depth error against run time
# (called by Allrun with ladder='25 50 ...').
set terminal pngcairo size 900,600 noenhanced
set output 'depth.png'
set xlabel 'time [us]'
set ylabel 'penetration depth [mm]'
set title 'Steel disk into aluminium at 1160 m/s (seed 4.2): depth of the disk centre'
set key bottom right
set xrange [0:80]
set yrange [0:26]
plot for [n in ladder] 'ladder/USF-'.n.'/series.dat' using 1:2 with lines lw 2 title n.' x '.n.' cells', \
     19 with lines dt 2 lc rgb 'black' title 'seed, 50 x 50 cells (19 mm)', \
     20 with lines dt 3 lc rgb 'gray40' title 'CTH, Silling 1992 (20 mm)', \
     21 with lines dt 4 lc rgb 'red' title 'experiment, Trucano & Grady 1985 (21 mm)'

set output 'error.png'
set logscale x
unset xrange
set autoscale y
set xlabel 'wall time [s]'
set ylabel 'final depth - 19 mm [% of 19 mm]'
set title 'Impact: final depth against the seed over the ladder, against run time'
set key top left
plot for [s in 'USF MUSL'] 'errors.dat' using (strcol(1) eq s ? $5 : NaN):8 with linespoints pt 7 title s, \
     0 with lines dt 2 lc rgb 'black' notitle
