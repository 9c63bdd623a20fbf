# Runout and final height against the aspect ratio with Lube et al.'s laws (errors.dat, written
# by Allrun), and the deposits at a = 4 (deposit-a4-*.dat).
set terminal pngcairo size 1200,500 noenhanced
set output 'runout.png'
set multiplot layout 1,2 title 'Column collapse: muI (glass beads) and mohrCoulomb (the same friction) against Lube et al. 2005'
set logscale xy
set xlabel 'a = H / L0'
set key top left
set grid
lube(a) = a < 2.3 ? 1.2 * a : 1.9 * a**(2.0/3)
height(a) = a < 1.15 ? a : a**0.4
set samples 200
set xrange [0.4:10]
set ylabel '(L_inf - L0) / L0'
plot lube(x) with lines lw 2 lc rgb 'black' title 'Lube: 1.2 a, 1.9 a^(2/3)', \
     for [h in system("awk '!/^#/ {print $2}' errors.dat | sort -u")] \
         sprintf("< awk '!/^#/ && $3 == \"muI\" && $2 == %s' errors.dat", h) using 1:10 with linespoints pt 7 title 'muI, h '.h, \
     for [h in system("awk '!/^#/ {print $2}' errors.dat | sort -u")] \
         sprintf("< awk '!/^#/ && $3 == \"mohrCoulomb\" && $2 == %s' errors.dat", h) using 1:10 with linespoints pt 5 title 'mohrCoulomb, h '.h
set ylabel 'H_inf / L0'
plot height(x) with lines lw 2 lc rgb 'black' title 'Lube: a, a^(2/5)', \
     for [h in system("awk '!/^#/ {print $2}' errors.dat | sort -u")] \
         sprintf("< awk '!/^#/ && $3 == \"muI\" && $2 == %s' errors.dat", h) using 1:12 with linespoints pt 7 title 'muI, h '.h, \
     for [h in system("awk '!/^#/ {print $2}' errors.dat | sort -u")] \
         sprintf("< awk '!/^#/ && $3 == \"mohrCoulomb\" && $2 == %s' errors.dat", h) using 1:12 with linespoints pt 5 title 'mohrCoulomb, h '.h
unset multiplot

set output 'deposit.png'
set terminal pngcairo size 1200,350 noenhanced
unset logscale
set autoscale
set size ratio -1
set xlabel 'x1 [m]'
set ylabel 'x2 [m]'
set title 'The deposits at rest, a = 4 (the column stood 0.1 m wide, 0.4 m high)'
files = system('ls deposit-a4-*.dat 2> /dev/null')
set key top right
plot for [f in files] f using 1:2 with points pt 7 ps 0.3 title f[9:strlen(f)-4]
