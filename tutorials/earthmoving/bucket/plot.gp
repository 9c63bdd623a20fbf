# Dragline bucket in corn (seed 6.2.6, fig. 6.25): draft force against travel for the runs
# (runs='dir ...', given by Allrun), and the draft force at 100 mm against run time.
set terminal pngcairo size 900,650 noenhanced
set output 'force.png'
set xlabel 'bucket travel x1 [mm]'
set ylabel 'draft force F_x1 of the bucket on the corn [N/m]  (x 0.2 m: N in the rig)'
set title "Dragline bucket in corn (seed 6.2.6, fig. 6.25)\nshaded: the seed's bounds on the measured force up to 600 mm (100 ... 1250 N/m)"
set key outside bottom center horizontal maxrows 3
set xrange [0:*]
set yrange [0:1500]   # the measured band and a little over: a run stopped by a blow-up ends in a spike
set object 1 rectangle from first 0, first 100 to first 600, first 1250 behind fc rgb '#ffe0e0' fs solid noborder
plot NaN with boxes fs solid fc rgb '#ffe0e0' title 'measured, up to 600 mm: 20 ... 250 N (seed text and axis)', \
     for [r in runs] r.'/series.dat' using 1:2 with lines lw 1 title r[8:]

set output 'error.png'
unset object 1
set xrange [*:*]
set yrange [0:1500]   # the measured band and a little over: a run stopped by a blow-up ends in a spike
set logscale x
set xlabel 'wall time [s]'
set ylabel 'draft force F_x1 at 100 mm of travel [N/m]'
set title 'Dragline bucket: draft force at 100 mm against run time (labels: cell size [m])'
set key outside bottom center horizontal
plot 'errors.dat' using (strcol(7) eq "prescribed" ? $5 : NaN):10 with linespoints pt 7 lc rgb 'black' title 'prescribed velocity', \
     'errors.dat' using (strcol(7) eq "weighted" ? $5 : NaN):10 with points pt 5 ps 1.5 lc rgb 'blue' title 'riding on its weight', \
     'errors.dat' using 5:10:2 with labels offset 0,1 notitle, \
     100 with lines dt 2 lc rgb 'red' title "seed's lower bound (20 N)"
