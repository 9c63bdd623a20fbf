# Silo discharge (seed 4.6, fig. 4.31): flow rate against time after the opening with the
# Beverloo lines; the error of the steady rate against wall time over the ladder.
# Call with -e "run='ladder/silo-0.005'".
set terminal pngcairo size 800,500
set output 'flowRate.png'
set xlabel 'time after opening [s]'
set ylabel 'mass flow rate [kg/s per m]'
set yrange [0:220]
set key bottom right
set grid
plot run.'/series.dat' using 1:2 with lines lw 2 title 'granular-pic (whole silo)', \
     '' using 1:3 with lines dt 2 lc rgb 'black' title 'Beverloo, d/D = 0', \
     '' using 1:4 with lines dt 3 lc rgb 'black' title 'Beverloo, d/D = 0.1'

set output 'error.png'
set logscale xy
set xlabel 'wall time [s]'
set ylabel '|steady rate - Beverloo (d/D = 0)| / Beverloo [%]'
set autoscale y
set key top right
plot 'errors.dat' using 5:(abs($7)) with linespoints pt 7 title 'granular-pic'
