# Stresses across the wall against Lame (the run in run='...', given by Allrun), and the
# error of the ladder against run time.
set terminal pngcairo size 900,650 noenhanced
set output 'stress.png'
shown = run.'/stress.dat'
set xlabel 'distance from the centre rho [m]'
set ylabel 'stress [kPa], tension positive'
set title 'Thick sphere, a 0.1 m, b 0.2 m, p 10 kPa: shell means ('.run.')'
set key outside right
plot shown using 1:($5/1e3) with lines lw 2 lc rgb 'blue' title 'sigma_rhorho, Lame', \
     shown using 1:($6/1e3) with lines lw 2 lc rgb 'red' title 'sigma_thetatheta, Lame', \
     shown using 1:($7/1e3) with lines lw 2 lc rgb 'dark-green' title 'sigma_phiphi, Lame', \
     shown using 1:($2/1e3) with points pt 7 lc rgb 'blue' title 'sigma_rhorho', \
     shown using 1:($3/1e3) with points pt 5 lc rgb 'red' title 'sigma_thetatheta', \
     shown using 1:($4/1e3) with points pt 9 lc rgb 'dark-green' title 'sigma_phiphi'

set output 'error.png'
set logscale xy
set xlabel 'wall time [s]'
set ylabel 'error [%]'
set title 'Thick-walled sphere: error against run time'
set key top right
plot 'errors.dat' using 4:5 with linespoints pt 7 lw 2 title 'stress, % of p', \
     'errors.dat' using 4:(abs($6)) with linespoints pt 5 lw 2 title 'inner displacement, % of u'
