# force.png: the thrust P_h against travel for every run, with the references; error.png:
# the error against the wall time (errors.dat).
set terminal pngcairo size 1100,450 font ",10"
set output 'force.png'
set multiplot layout 1,2
active = system("ls -d ladder/active-*-0 2> /dev/null")
passive = system("ls -d ladder/passive-*-0 2> /dev/null")
set xlabel 'travel [mm]'; set ylabel 'P_h [N/m]'; set key outside bottom center horizontal font ",8"
set title 'active (away from the backfill)'
plot for [r in active] r.'/series.dat' using 1:2 with lines title r[8:], \
     2452.5 with lines dt 2 lc 'black' title 'Rankine', 2056 with lines dt 3 lc 'black' title 'Coulomb, delta 20'
set title 'passive (into the backfill)'
plot for [r in passive] r.'/series.dat' using 1:2 with lines title r[8:], \
     22072.5 with lines dt 2 lc 'black' title 'Rankine', 36338 with lines dt 3 lc 'black' title 'Sokolovski, delta 20'
unset multiplot
set output 'error.png'
set terminal pngcairo size 700,450 font ",10"
set title 'error of P_h against run time'; set xlabel 'wall time [s]'; set ylabel 'error [%]'; set logscale x
set key top right
plot 'errors.dat' using 7:(strcol(1) eq 'active' && strcol(2) eq 'smooth' ? $12 : 1/0) with linespoints title 'active smooth', \
     '' using 7:(strcol(1) eq 'active' && strcol(2) eq 'rough' ? $12 : 1/0) with linespoints title 'active rough', \
     '' using 7:(strcol(1) eq 'passive' && strcol(2) eq 'smooth' ? $12 : 1/0) with linespoints title 'passive smooth', \
     '' using 7:(strcol(1) eq 'passive' && strcol(2) eq 'rough' ? $12 : 1/0) with linespoints title 'passive rough', 0 notitle lc 'black'
