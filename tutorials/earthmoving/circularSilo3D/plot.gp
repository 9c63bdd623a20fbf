# Cylindrical silo, 3D quarter and axisymmetric twin: mass in the silo against time after the
# opening, each run with its Beverloo line (from the mass 0.2 s after the opening), and the
# error of the mean flow rate against wall time. Call with -e "runs='ladder/a ladder/b'".
set terminal pngcairo size 900,600 noenhanced
set output 'mass.png'
set xlabel 'time after the opening [s]'
set ylabel 'mass in the silo [kg]'
set title 'Cylindrical silo, corn: mass in the silo (lines) and Beverloo at the opened diameter (dashed)'
set key outside bottom center horizontal maxrows 4
set grid
plot for [r in runs] r.'/series.dat' using 1:2 with lines lw 2 title r[8:], \
     for [r in runs] r.'/series.dat' using 1:3 with lines dt 2 lw 1 lc rgb 'gray40' notitle

set output 'error.png'
set logscale x
set xlabel 'wall time [s]'
set ylabel '(flow rate - Beverloo) / Beverloo [%]'
set title 'Cylindrical silo: error of the mean flow rate against wall time (labels: D mm, cells across the radius)'
set yrange [-60:60]
set key bottom right
plot 'errors.dat' using 6:(strcol(3) eq 'threeD' ? $11 : 1/0) with points pt 7 ps 1.5 lc rgb 'black' title '3D quarter', \
     '' using 6:(strcol(3) eq 'axisymmetric' ? $11 : 1/0) with points pt 6 ps 1.5 lc rgb 'black' title 'axisymmetric', \
     '' using 6:11:(sprintf('D%s n%s', strcol(1), strcol(2))) with labels offset 0,1 font ',8' notitle, \
     0 with lines dt 2 lc rgb 'gray50' notitle
