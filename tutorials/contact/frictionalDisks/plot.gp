# Energies of the case run (dt 1e-3 s) and the energy drift after separation against wall time.
set terminal pngcairo size 900,600
set output 'energy.png'
set xlabel 'time [s]'
set ylabel 'energy [J per m thickness]'
set title 'Two elastic disks with Coulomb contact (mu 0.1): kinetic, strain and total energy'
set key center right
plot 'series.dat' using 1:2 with lines lw 2 title 'kinetic', \
     'series.dat' using 1:3 with lines lw 2 title 'strain (stress work)', \
     'series.dat' using 1:4 with lines lw 2 title 'total'

set output 'error.png'
set logscale xy
set xlabel 'wall time [s]'
set ylabel 'energy change after separation [% of start]'
set title 'Two disks: energy drift once apart, against run time (ladder of time steps)'
set key top right
plot 'errors.dat' using (strcol(1) eq 'coulombFriction' ? $5 : NaN):7 with linespoints pt 7 lw 2 title 'coulombFriction', \
     'errors.dat' using (strcol(1) eq 'noSlip' ? $5 : NaN):7 with linespoints pt 5 lw 2 title 'noSlip'
