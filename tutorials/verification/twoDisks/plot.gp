# Energies of the case run (dt 1e-3 s) and the energy error against wall time of the ladder.
set terminal pngcairo size 900,600
set output 'energy.png'
set xlabel 'time [s]'
set ylabel 'energy [J per m thickness]'
set title 'Two elastic disks (seed 4.4): kinetic, strain and total energy'
set key center right
plot 'series.dat' using 1:2 with lines lw 2 title 'kinetic', \
     'series.dat' using 1:3 with lines lw 2 title 'strain (stress work)', \
     'series.dat' using 1:4 with lines lw 2 title 'total'

set output 'error.png'
set logscale xy
set xlabel 'wall time [s]'
set ylabel 'largest energy error [% of start]'
set title 'Two disks: energy error against run time (seed table 4.3 dashed)'
set key top right
max(a, b) = a > b ? a : b
plot for [s in 'USF MUSL USL'] 'errors.dat' using (strcol(1) eq s ? $5 : NaN):(max($6, $7)) \
         with linespoints pt 7 title s, \
     'errors.dat' using (strcol(1) eq 'USF' ? $5 : NaN):(max($9, $10)) with linespoints dt 2 title 'seed'
