# Shear zones of the bucket in corn (seed figs. 6.32-6.34): the particle displacement ratio
# PDR = |particle displacement| / |bucket displacement| over about 10 mm of travel, in the
# seed's colour bands, at the particles' positions at the start of the increment; the bucket
# in black. Given: data (pdr.csv of picDisplacementRatio), bucket (its outline), out, name.
set terminal pngcairo size 1100,520 noenhanced
set output out
set size ratio -1
set datafile separator ','
set xlabel 'x1 [m]'
set ylabel 'x2 [m]'
set title 'PDR: '.name.' (seed bands: >= 0.95 red, 0.80 dark orange, 0.65 light orange, 0.40 yellow, 0.25 green, 0.10 blue, < 0.10 white)'
set palette defined (0 'white', 0.0999 'white', 0.1 'blue', 0.2499 'blue', 0.25 'green', 0.3999 'green', \
    0.4 'yellow', 0.6499 'yellow', 0.65 '#ffb347', 0.7999 '#ffb347', 0.8 '#ff8c00', 0.9499 '#ff8c00', 0.95 'red', 1 'red')
set cbrange [0:1]
set cblabel 'PDR'
set key off
stats bucket using 1 nooutput
set xrange [STATS_min - 0.25:STATS_max + 0.6]
set yrange [0.1:0.6]
set object 1 rectangle from graph 0,0 to graph 1,1 behind fc rgb 'grey90' fs solid noborder
plot data every ::1 using 1:2:($3 > 1 ? 1 : $3) with points pt 5 ps 0.4 lc palette, \
     bucket using 1:2 with lines lw 2 lc rgb 'black' notitle
