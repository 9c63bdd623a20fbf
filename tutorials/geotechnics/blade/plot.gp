# Blade (seed 4.7): forces against blade travel for the runs at h = 0.21 m (runs='dir ...',
# given by Allrun), forces against depth, and the error of the ladder against run time.
set terminal pngcairo size 900,650 noenhanced
S1 = 1704.72; S2 = -340.94   # Sokolovski at h = 0.21 m (picSokolovski -phi 35 -mu 0.2 -rho 1500)

set output 'force.png'
set xlabel 'blade travel [mm]'
set ylabel 'force of the blade on the sand x (0.21/h)^2 [N/m]'
set title 'Blade (seed 4.7, fig. 4.35/4.41), h = 0.21 m: F_x1 and F_x2 (mean over 10 ... 35 mm)'
set key outside bottom center horizontal maxrows 3
set xrange [0:35]
set arrow from 10, graph 0 to 10, graph 1 nohead dt 3 lc rgb 'gray50'
plot for [r in runs] r.'/series.dat' using 1:4 with lines lw 1 title 'F_x1 '.r[8:], \
     for [r in runs] r.'/series.dat' using 1:5 with lines lw 1 title 'F_x2 '.r[8:], \
     S1 with lines lw 2 lc rgb 'black' title 'F_x1 Sokolovski', \
     S2 with lines lw 2 dt 2 lc rgb 'black' title 'F_x2 Sokolovski', \
     S1 + 64 with lines dt 3 lc rgb 'gray40' title 'seed: F_x1 64 ... 103 N/m above Sokolovski', \
     S1 + 103 with lines dt 3 lc rgb 'gray40' notitle
unset arrow

set output 'depth.png'
set xlabel 'blade depth h [m]'
set ylabel 'mean force of the blade on the sand [N/m]'
set title 'Blade (seed 4.7, figs. 4.36/4.37): mean forces against depth (labels: cells across)'
set key default
set key top left
set xrange [0:0.35]
plot 'sokolovski.dat' using 1:2 with lines lw 2 lc rgb 'black' title 'F_x1 Sokolovski', \
     'sokolovski.dat' using 1:3 with lines lw 2 dt 2 lc rgb 'black' title 'F_x2 Sokolovski', \
     'sokolovski.dat' using 1:($2 + 64):($2 + 103) with filledcurves fs transparent solid 0.25 \
         lc rgb 'orange' title 'seed (100 x 50): F_x1 64 ... 103 N/m above', \
     'errors.dat' using 6:(strcol(1) eq 'fast' ? $8 : NaN) with points pt 7 ps 1.2 lc rgb 'blue' title 'F_x1 granular-pic, 50 mm/s', \
     'errors.dat' using 6:(strcol(1) eq 'fast' ? $9 : NaN) with points pt 5 ps 1.2 lc rgb 'blue' title 'F_x2 granular-pic, 50 mm/s', \
     'errors.dat' using 6:(strcol(1) eq 'seed' ? $8 : NaN) with points pt 6 ps 1.6 lw 2 lc rgb 'red' title 'F_x1 granular-pic, 5 mm/s', \
     'errors.dat' using 6:(strcol(1) eq 'seed' ? $9 : NaN) with points pt 4 ps 1.6 lw 2 lc rgb 'red' title 'F_x2 granular-pic, 5 mm/s', \
     'errors.dat' using 6:8:(sprintf('%d', $2)) with labels offset 2.5,0 notitle

set output 'error.png'
set xrange [*:*]
set logscale x
set xlabel 'wall time [s]'
set ylabel '(ours - Sokolovski) / Sokolovski [%]'
set title 'Blade, h = 0.21 m: error of the mean forces against run time (labels: cells across)'
set key default
set key below
plot 'errors.dat' using ($15 == 0.21 && strcol(1) eq 'fast' ? $5 : NaN):12 with linespoints pt 7 lc rgb 'blue' title 'F_x1, 50 mm/s', \
     'errors.dat' using ($15 == 0.21 && strcol(1) eq 'fast' ? $5 : NaN):13 with linespoints pt 5 dt 2 lc rgb 'blue' title 'F_x2, 50 mm/s', \
     'errors.dat' using ($15 == 0.21 && strcol(1) eq 'seed' ? $5 : NaN):12 with linespoints pt 6 lc rgb 'red' title 'F_x1, 5 mm/s', \
     'errors.dat' using ($15 == 0.21 && strcol(1) eq 'seed' ? $5 : NaN):13 with linespoints pt 4 dt 2 lc rgb 'red' title 'F_x2, 5 mm/s', \
     'errors.dat' using ($15 == 0.21 ? $5 : NaN):12:2 with labels offset 0,1 notitle, \
     6400 / S1 with lines dt 3 lc rgb 'gray40' title 'seed F_x1 (100 x 50): +3.8 ... +6.0 %', \
     10300 / S1 with lines dt 3 lc rgb 'gray40' notitle, \
     0 with lines lc rgb 'black' notitle
