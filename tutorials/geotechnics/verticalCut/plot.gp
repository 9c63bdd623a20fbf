# Footing pressure against settlement over the ladder (ladder/*/pressure.dat, listed in
# errors.dat) with field test A and the seed's failure load; and the error of P_fail against
# wall time.
set terminal pngcairo size 900,650 noenhanced
set output 'pressure.png'
runs = system("awk '!/^#/ { print $11 }' errors.dat")
set xlabel 'settlement [mm]'
set ylabel 'footing pressure P [kPa]'
set title 'Strip footing near a 2 m vertical cut (seed 5.3.4): b = 0.4 m, phi 27 deg, c 26 kPa'
set xrange [0:*]
set yrange [0:350]
set key bottom right
plot for [r in runs] r.'/pressure.dat' using 1:2 with lines lw 1.5 title r[8:], \
     150 with lines lw 2 dt 1 lc rgb 'black' title 'field test A: 150 kPa', \
     105 with lines dt 2 lc rgb 'red' title 'seed (PICCUS, PLAXIS) ~105 kPa (graphical)'

set output 'error.png'
set xrange [*:*]
set yrange [*:*]
set logscale xy
set xlabel 'wall time [s]'
set ylabel '|P_fail - 150 kPa| / 150 kPa [%]'
set title 'Footing near a cut: error of the failure pressure against run time (seed: 30 %)'
set key top right
plot for [m in 'cut slow'] 'errors.dat' using (strcol(1) eq m ? $5 : NaN):(abs($7)) \
         with linespoints pt 7 title m, \
     30 with lines dt 2 lc rgb 'black' title 'seed (30 %)'
