# The deposits of the first 3D run and its axisymmetric twin (dirs set by Allrun), as
# (distance from the axis, height) of every particle.
set terminal pngcairo size 900,400
set output 'deposit.png'
set size ratio -1
set xlabel 'r [m]'
set ylabel 'x2 [m]'
set key top right
set title 'cylinder collapse: the deposit at rest, 3D quarter and axisymmetric ('.solid.')'
plot solid.'/deposit.dat' using 1:2 with dots lc rgb '#8B5A2B' title '3D', \
     ring.'/deposit.dat' using 1:($2 + 0.0) with points pt 7 ps 0.3 lc rgb '#1f77b4' title 'axisymmetric'
