# Blade across the width (seed 4.7 in 3D): force per width against travel for each run
# (runs='dir ...', travel [mm], given by Allrun), the mean force per width against the
# blade's width with McKyes & Ali's, and the error against run time.
set terminal pngcairo size 900,650 noenhanced
S1 = 1546.2   # Sokolovski at h = 0.20 m (picSokolovski -phi 35 -mu 0.2 -rho 1500)

set output 'force.png'
set xlabel 'blade travel [mm]'
set ylabel 'force of the blade on the sand per width [N/m]'
set title 'Blade across the width (seed 4.7), h = 0.20 m: F_x1 per width (kind-cell-w)'
set key outside bottom center horizontal maxrows 4
set xrange [0:travel]
plot for [r in runs] r.'/series.dat' using 1:2 with lines lw 1 title r[8:], \
     S1 with lines lw 2 lc rgb 'black' title 'Sokolovski (plane strain)'

set output 'width.png'
set xlabel 'blade width w [m]'
set ylabel 'mean draft force per width [N/m]'
set title 'Blade across the width, h = 0.20 m: mean F_x1 per width against w'
set key default
set key top right
set xrange [0:2]
plot 'mckyesAli.dat' using 1:4 with lines lw 2 lc rgb 'black' title 'McKyes & Ali (1977)', \
     'mckyesAli.dat' using 1:6 with lines lw 1 dt 2 lc rgb 'black' title 'McKyes & Ali, plane strain (Coulomb)', \
     S1 with lines lw 1 dt 3 lc rgb 'gray30' title 'Sokolovski (plane strain)', \
     'errors.dat' using (strcol(1) eq 'free' && $2 == 0.05 ? $3 : NaN):9 with points pt 7 ps 1.5 lc rgb 'blue' title 'granular-pic, 50 mm cells', \
     'errors.dat' using (strcol(1) eq 'free' && $2 == 0.025 ? $3 : NaN):9 with points pt 5 ps 1.5 lc rgb 'red' title 'granular-pic, 25 mm cells', \
     'errors.dat' using (strcol(1) eq 'plane' ? 1.9 : NaN):9 with points pt 4 ps 1.5 lc rgb 'dark-green' title 'plane twin (drawn at w = 1.9)', \
     'errors.dat' using (strcol(1) eq 'slip' ? 0.2 : NaN):9 with points pt 6 ps 1.5 lc rgb 'orange' title 'rig, slip walls', \
     'errors.dat' using (strcol(1) eq 'glass' ? 0.2 : NaN):9 with points pt 8 ps 1.5 lc rgb 'purple' title 'rig, glass walls'

set output 'error.png'
set xrange [*:*]
set logscale x
set xlabel 'wall time [s]'
set ylabel 'error [%]'
set title 'Blade across the width: error against run time (labels: w [m])'
set key default
set key below
plot 'errors.dat' using (strcol(1) eq 'free' ? $7 : NaN):18 with points pt 7 lc rgb 'blue' title 'F_x1 per width against McKyes & Ali', \
     'errors.dat' using (strcol(1) eq 'free' && strcol(20) ne '-' ? $7 : NaN):(($20 - $21) / $21 * 100) with points pt 5 lc rgb 'red' title 'ratio to the plane twin against McKyes & Ali''s', \
     'errors.dat' using (strcol(1) eq 'plane' ? $7 : NaN):19 with points pt 4 lc rgb 'dark-green' title 'plane twin against Sokolovski', \
     'errors.dat' using (strcol(1) eq 'free' ? $7 : NaN):18:3 with labels offset 0,1 notitle
