# Normal and shear stress on the inside of the bucket (seed figs. 6.35, 6.36), against the
# distance s along the inside from the tooth's tip (tooth 0 ... 40 mm, floor to 240 mm, then
# the corner, the back wall and the hood). Given: data (stress-*.dat), out, name.
set terminal pngcairo size 900,550 noenhanced
set output out
set xlabel 's along the inside of the bucket from the tooth tip [mm]'
set ylabel 'stress [kPa]'
set title 'Stresses on the inside of the bucket: '.name."\nseed at 800 mm: max normal 15.1 (nonpolar), 9.8 (polar), 12.8 kPa (DEM), on the tooth"
set key top right
set arrow from 40, graph 0 to 40, graph 1 nohead dt 3 lc rgb 'gray50'
set arrow from 240, graph 0 to 240, graph 1 nohead dt 3 lc rgb 'gray50'
plot data using 1:3 with linespoints pt 7 ps 0.6 lc rgb 'black' title 'normal stress', \
     data using 1:4 with linespoints pt 6 ps 0.6 lc rgb 'red' title 'shear stress', \
     15.1 with lines dt 2 lc rgb 'black' title 'seed nonpolar max normal', \
     3.5 with lines dt 2 lc rgb 'red' title 'seed nonpolar max shear'
