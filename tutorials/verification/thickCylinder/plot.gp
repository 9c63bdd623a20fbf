# Stresses across the wall against Lame (the run in run='...', given by Allrun), and the
# error of the ladder against run time.
set terminal pngcairo size 900,650 noenhanced
set output 'stress.png'
shown = run.'/stress.dat'
set xlabel 'radius r [m]'
set ylabel 'stress [kPa], tension positive'
set title 'Thick-walled cylinder, a = 0.1 m, b = 0.2 m, p = 10 kPa: column means ('.run.')'
set key outside right
plot shown using 1:($5/1e3) with lines lw 2 lc rgb 'blue' title 'sigma_rr, Lame', \
     shown using 1:($6/1e3) with lines lw 2 lc rgb 'red' title 'sigma_tt, Lame', \
     shown using 1:($7/1e3) with lines lw 2 lc rgb 'dark-green' title 'sigma_zz, Lame', \
     shown using 1:($2/1e3) with points pt 7 lc rgb 'blue' title 'sigma_rr', \
     shown using 1:($3/1e3) with points pt 5 lc rgb 'red' title 'sigma_tt', \
     shown using 1:($4/1e3) with points pt 9 lc rgb 'dark-green' title 'sigma_zz'

set output 'error.png'
set logscale xy
set xlabel 'wall time [s]'
set ylabel 'error [%]'
set title 'Thick-walled cylinder: error against run time'
set key top right
axi(c) = strcol(8) eq 'plane' ? NaN : column(c)
plane(c) = strcol(8) eq 'plane' ? column(c) : NaN
plot 'errors.dat' using 4:(axi(5)) with linespoints pt 7 lw 2 lc rgb 'blue' title 'axisymmetric: stress, % of p', \
     'errors.dat' using 4:(abs(axi(6))) with linespoints pt 5 lw 2 lc rgb 'red' title 'axisymmetric: inner displacement, % of u', \
     'errors.dat' using 4:(plane(5)) with linespoints pt 6 lw 2 dt 2 lc rgb 'blue' title 'plane strain: stress', \
     'errors.dat' using 4:(abs(plane(6))) with linespoints pt 4 lw 2 dt 2 lc rgb 'red' title 'plane strain: inner displacement'
