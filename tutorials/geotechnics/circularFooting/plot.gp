# Footing pressure against settlement over the ladder (ladder/*/pressure.dat, listed in
# errors.dat) with the references, and the error of q_u against wall time.
set terminal pngcairo size 900,650 noenhanced
set output 'pressure.png'
runs = system("awk '!/^#/ { print $12 }' errors.dat")
silt = system("awk '$1 == \"silt\"' errors.dat | wc -l") + 0
set xlabel 'settlement [mm]'
set xrange [0:*]
set key bottom right
if (silt) {
    set ylabel 'footing pressure P [kPa]'
    set title 'Rough circular footing, R = 0.2 m, on Heilbronn silt (phi 27 deg, c 26 kPa), axisymmetric'
    set yrange [0:1400]
    set arrow from 30, graph 0 to 30, graph 1 nohead dt 3 lc rgb 'gray'
    set arrow from 50, graph 0 to 50, graph 1 nohead dt 3 lc rgb 'gray'
    plot for [r in runs] r.'/pressure.dat' using 1:2 with lines lw 1.5 title r[8:], \
         996.3 with lines lw 2 lc rgb 'black' title 'strip factors x shape factors, 996 kPa', \
         696.1 with lines dt 2 lc rgb 'blue' title 'strip, footingBearing on 0.04 m cells, 696 kPa', \
         674 with lines dt 3 lc rgb 'blue' title 'strip, c N_c + gamma b N_b = 674 kPa'
} else {
    set ylabel 'footing pressure P / c'
    set title 'Rough circular footing, R = 0.2 m, on a weightless Tresca soil (c 26 kPa), axisymmetric'
    set yrange [0:12]
    set arrow from 10, graph 0 to 10, graph 1 nohead dt 3 lc rgb 'gray'
    set arrow from 15, graph 0 to 15, graph 1 nohead dt 3 lc rgb 'gray'
    plot for [r in runs] r.'/pressure.dat' using 1:3 with lines lw 1.5 title r[8:], \
         6.05 with lines lw 2 lc rgb 'black' title 'rough circle, Eason & Shield 6.05 c', \
         5.69 with lines dt 2 lc rgb 'red' title 'smooth circle, Shield 5.69 c', \
         2 + pi with lines dt 3 lc rgb 'blue' title 'strip, Prandtl 5.14 c'
}

set output 'error.png'
unset arrow
set xrange [*:*]
set yrange [*:*]
set logscale xy
set xlabel 'wall time [s]'
set ylabel '|q_u - reference| / reference [%]'
set title 'Rough circular footing: error of the collapse pressure against run time'
set key top right
models = system("awk '!/^#/ && !seen[$1]++ { printf \"%s \", $1 }' errors.dat")
plot for [m in models] 'errors.dat' using (strcol(1) eq m ? $6 : NaN):(abs($8)) \
         with linespoints pt 7 title m
