# Blade in corn (seed 6.2.5): draft force against blade travel for the runs at h = 0.35 m
# (runs='dir ...', given by Allrun) and the error of the mean draft force against run time.
set terminal pngcairo size 900,650 noenhanced
S1 = 1669.3    # Sokolovski at h = 0.35 m (picSokolovski -phi 26 -mu 0.249 -rho 778)
E1 = 1926.1    # experiment, derived: S1 x 1.05 / 0.91 (seed: nonpolar +5 % on S1, -9 % on it)

set output 'force.png'
set xlabel 'blade travel [mm]'
set ylabel 'draft force F_x1 of the blade on the corn [N/m]  (x 0.2 m: N in the rig)'
set title 'Blade in corn (seed 6.2.5, figs. 6.12-6.14), h = 0.35 m (mean over 15 ... 35 mm)'
set key outside bottom center horizontal maxrows 4
set xrange [0:35]
set yrange [0:*]
set arrow from 15, graph 0 to 15, graph 1 nohead dt 3 lc rgb 'gray50'
plot for [r in runs] r.'/series.dat' using 1:2 with lines lw 1 title r[8:], \
     S1 with lines lw 2 lc rgb 'black' title 'Sokolovski', \
     E1 with lines lw 2 dt 2 lc rgb 'red' title 'experiment (derived)', \
     1.05 * S1 with lines dt 3 lc rgb 'gray40' title 'seed nonpolar (+5 %)', \
     0.80 * E1 with lines dt 4 lc rgb 'blue' title 'seed polar (-20 % on the experiment)'
unset arrow

set output 'error.png'
set xrange [*:*]
set yrange [-35:45]
set logscale x
set xlabel 'wall time [s]'
set ylabel '(ours - reference) / reference [%]'
set title 'Blade in corn, h = 0.35 m: error of the mean draft force against run time (labels: cell size)'
set key outside bottom center horizontal maxrows 4
plot 'errors.dat' using (strcol(6) eq 'nonpolar' && $7 == 2 ? $5 : NaN):14 with linespoints pt 7 lc rgb 'black' title 'nonpolar vs Sokolovski', \
     'errors.dat' using (strcol(6) eq 'nonpolar' && $7 == 2 ? $5 : NaN):(strcol(17) eq '-' ? NaN : $17) with linespoints pt 5 dt 2 lc rgb 'red' title 'nonpolar vs experiment', \
     'errors.dat' using (strcol(6) eq 'polar' ? $5 : NaN):14 with points pt 6 ps 1.5 lw 2 lc rgb 'black' title 'polar vs Sokolovski', \
     'errors.dat' using (strcol(6) eq 'polar' ? $5 : NaN):(strcol(17) eq '-' ? NaN : $17) with points pt 4 ps 1.5 lw 2 lc rgb 'red' title 'polar vs experiment', \
     'errors.dat' using ($7 == 2 ? $5 : NaN):14:2 with labels offset 0,1 notitle, \
     5 with lines dt 3 lc rgb 'black' title 'seed nonpolar vs Sokolovski (+5 %)', \
     -9 with lines dt 3 lc rgb 'red' title 'seed nonpolar vs experiment (-9 %)', \
     -20 with lines dt 4 lc rgb 'blue' title 'seed polar vs experiment (-20 %)', \
     0 with lines lc rgb 'gray50' notitle
