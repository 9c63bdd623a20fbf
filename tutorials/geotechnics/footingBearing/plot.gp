# Footing pressure against settlement over the ladder (ladder/*/pressure.dat, listed in
# errors.dat), with the bearing capacity of eqs. 5.3.1-5.3.2 and the seed's failure loads;
# and the error of P_max against wall time.
set terminal pngcairo size 900,650 noenhanced
set output 'pressure.png'
runs = system("awk '!/^#/ { print $11 }' errors.dat")
set xlabel 'settlement [mm]'
set ylabel 'footing pressure P [kPa]'
set title 'Strip footing on Heilbronn silt (seed 5.3.3): b = 0.4 m, phi 27 deg, c 26 kPa'
set xrange [0:*]
set yrange [0:1000]
set key bottom right
plot for [r in runs] r.'/pressure.dat' using 1:2 with lines lw 1.5 title r[8:], \
     674 with lines lw 2 dt 1 lc rgb 'black' title 'c N_c + gamma b N_b = 674 kPa', \
     692 with lines dt 2 lc rgb 'red' title 'seed (PICCUS) 692 kPa', \
     668 with lines dt 3 lc rgb 'blue' title 'PLAXIS 668 kPa'

set output 'error.png'
set xrange [*:*]
set yrange [*:*]
set logscale xy
set xlabel 'wall time [s]'
set ylabel '|P_max - 674 kPa| / 674 kPa [%]'
set title 'Strip footing: error of the bearing capacity against run time (seed: 2.7 %)'
set key top right
plot for [m in 'rough slow smooth'] 'errors.dat' using (strcol(1) eq m ? $5 : NaN):(abs($7)) \
         with linespoints pt 7 title m, \
     2.7 with lines dt 2 lc rgb 'black' title 'seed (2.7 %)'
