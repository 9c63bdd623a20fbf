# The bucket of seed fig. 6.3 as reconstructed (bucketProfile.py -dat bucket.dat): the outline
# in 15 mm plates and the inside faces along which the stresses are taken.
set terminal pngcairo size 800,650 noenhanced
set output 'bucket.png'
set size ratio -1
set xlabel 'x [mm] (the bucket moves in +x)'
set ylabel 'y [mm]'
set title "Dragline bucket of seed fig. 6.3 as reconstructed (mm)\nlabels placed: 200, R_i 100, 190, 75, 140, 40 deg, 40, 15; not placed: 93"
set grid
set key top right box opaque
set xrange [-40:260]
set yrange [-60:210]
set arrow 1 from -15,-48 to 200,-48 heads; set label 1 '215 = 200 + 15' at 60,-56
set arrow 2 from 0,5 to 200,5 heads lc rgb 'gray40'; set label 2 '200' at 95,12
set arrow 3 from -30,-15 to -30,175 heads; set label 3 '190' at -38,80 rotate by 90
set arrow 4 from -15,190 to 60,190 heads lc rgb 'gray40'; set label 4 '75' at 15,198
set arrow 5 from 60,182 to 200,182 heads lc rgb 'gray40'; set label 5 '140' at 125,190
set arrow 6 from 100,100 to 29.3,29.3 lc rgb 'gray40'; set label 6 'R_i 100' at 60,75
set label 7 'tooth 40, 40 deg' at 205,-5
plot 'bucket.dat' index 0 using 1:2 with filledcurves closed fc rgb 'gray70' title 'bucket (15 mm plates)', \
     'bucket.dat' index 0 using 1:2 with lines lc rgb 'black' notitle, \
     'bucket.dat' index 1 using 1:2 with linespoints pt 7 ps 0.6 lw 2 lc rgb 'red' title 'inside faces (stresses)'
