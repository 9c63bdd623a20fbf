# Blade in corn on turned meshes (seed fig. 6.19): the band's outer edge (edge.dat) and the
# draft force (series.dat) of every run, in the rig's frame. Given: runs='dir ...'.
set terminal pngcairo size 900,560 noenhanced
set output 'band.png'
set size ratio -1
set xlabel 's from the blade front [m]'
set ylabel 'n above the floor [m]'
set title 'Outer edge of PDR >= 0.15 over 5 ... 15 mm of travel (h = 0.35 m; Sokolovski: surface at 2h = 0.70 m)'
set key outside right
set xrange [0:0.85]
set yrange [0:0.5]
set arrow from 0, 0.1 to 0, 0.45 nohead lw 4 lc rgb 'gray30'
plot for [r in runs] r.'/edge.dat' using 1:2 with linespoints pt 7 ps 0.6 title r[8:], \
     '+' using (0.70):(0.45) with points pt 9 ps 2 lc rgb 'black' title 'Sokolovski x_s'
unset arrow
set output 'force.png'
set size noratio
set xlabel 'blade travel [mm]'
set ylabel 'draft force F_x1 of the blade on the corn [N/m]'
set title 'Blade in corn, h = 0.35 m: the draft force along the floor, upright and turned meshes'
set xrange [0:35]
set yrange [0:*]
plot for [r in runs] r.'/series.dat' using 1:2 with lines title r[8:], \
     1669.3 with lines lw 2 lc rgb 'black' title 'Sokolovski'
