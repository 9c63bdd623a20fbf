# The settled stress of the layered fill against the confined elastic column.
set terminal pngcairo size 900,650 noenhanced
set output 'stress.png'
set xlabel 'stress [kPa], tension positive'
set ylabel 'depth below the surface H - x2 [m]'
set title 'Layer-by-layer fill (seed 3.3.3), 20 layers, elastic, K0 of the layers 0.5 (Jaky)'
set yrange [2:0]
set key bottom left
plot 'profile.dat' using 4:1 with lines lw 2 lc rgb 'blue' title 'sigma22 = -rho g (H - x2)', \
     'profile.dat' using 5:1 with lines lw 2 lc rgb 'red' title 'sigma11 = nu/(1-nu) sigma22', \
     'profile.dat' using 2:1 with points pt 7 ps 0.6 lc rgb 'blue' title 'sigma22, granular-pic', \
     'profile.dat' using 3:1 with points pt 5 ps 0.6 lc rgb 'red' title 'sigma11, granular-pic'
