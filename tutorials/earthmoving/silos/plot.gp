# Plane silo (seed 6.3, figs. 6.41-6.42): mass in the silo against time after the opening,
# each run with its Beverloo line (from the mass 0.2 s after the opening), and the error of
# the mean flow rate against wall time. Call with -e "runs='ladder/a ladder/b'".
set terminal pngcairo size 900,600 noenhanced
set output 'mass.png'
set xlabel 'time after the opening [s]'
set ylabel 'mass in the silo [kg] (0.73 m deep)'
set title 'Plane silo, seed 6.3: mass in the silo (lines) and Beverloo at the opened width (dashed)'
set key outside bottom center horizontal maxrows 4
set yrange [0:*]
set grid
plot for [r in runs] r.'/series.dat' using 1:2 with lines lw 2 title r[8:], \
     for [r in runs] r.'/series.dat' using 1:3 with lines dt 2 lw 1 lc rgb 'gray40' notitle

set output 'error.png'
set logscale x
set xlabel 'wall time [s]'
set ylabel '(flow rate - Beverloo) / Beverloo [%]'
set title 'Plane silo: error of the mean flow rate against wall time (labels: material, w, psi, cells)'
set yrange [-60:60]
set key top right
plot 'errors.dat' using 5:14 with points pt 7 ps 1.5 lc rgb 'black' notitle, \
     '' using 5:14:(sprintf('%s %s w%s psi%s n%s', strcol(6), strcol(7), strcol(8), strcol(9), strcol(2))) \
        with labels offset 0,1 font ',8' notitle, \
     0 with lines dt 2 lc rgb 'gray50' notitle
