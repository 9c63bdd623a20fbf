# Load against displacement over the runs (ladder/*/load.dat, listed in errors.dat): the
# vertical anchor's P/B [kPa] with the experiment (seed 5.2.1) and the closed forms; the 45 deg
# anchor's P/(gamma B h) (seed 5.2.2); and the error of the peak against wall time.
set terminal pngcairo size 1200,550 noenhanced
set output 'load.png'
set multiplot layout 1,2
vruns = system("awk '!/^#/ && $1 == \"vertical\" { print $17 }' errors.dat")
iruns = system("awk '!/^#/ && $1 == \"inclined\" { print $17 }' errors.dat")
set xlabel 'anchor displacement [mm]'
set ylabel 'load factor P/B [kPa]'
set title 'Vertical pull-out (seed 5.2.1): B = 51 mm, phi 32, K0 0.47'
set xrange [0:*]
set yrange [0:*]
set key bottom right font ',9'
plot for [r in vruns] r.'/load.dat' using 1:2 with lines lw 1.5 title r[8:], \
     6.25 with lines dt 2 lc rgb 'black' title 'experiment h/B 3 (about 6.25 kPa)', \
     14.1 with lines dt 3 lc rgb 'black' title 'experiment h/B 5 (about 14.1 kPa)'
set ylabel 'load factor P/(gamma B h) [-]'
set title 'Anchor pulled at 45 deg (seed 5.2.2): phi 44, K0 0.31'
plot for [r in iruns] r.'/load.dat' using 1:2 with lines lw 1.5 title r[8:], \
     2.5 with lines dt 2 lc rgb 'black' title 'seed h/B 2 (fig. 5.8, about 2.5)'
unset multiplot

set terminal pngcairo size 900,650 noenhanced
set output 'error.png'
set xrange [*:*]
set yrange [*:*]
set logscale xy
set xlabel 'wall time [s]'
set ylabel '|ours - reference| / reference [%]'
set title 'Anchors: error against run time (seed: within 5 % of the experiments)'
set key top right
plot 'errors.dat' using (strcol(1) eq 'vertical' && $6 == 3 ? $5 : NaN):(abs($16)) \
         with linespoints pt 7 title 'vertical h/B 3: q_u against 6.25 kPa', \
     'errors.dat' using (strcol(1) eq 'inclined' && $6 == 2 ? $5 : NaN):(abs($16)) \
         with linespoints pt 5 title '45 deg h/B 2: N(1.6 mm) against the seed 2.5', \
     5 with lines dt 2 lc rgb 'black' title 'seed (5 %)'
