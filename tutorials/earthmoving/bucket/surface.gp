# Free surface of the corn every 100 mm of bucket travel (seed fig. 6.30), from
# picFreeSurface (the top of the highest corn particle per column). Given: data (one block
# per 100 mm), n (blocks), x0 (the bucket's back at the start), out, name.
set terminal pngcairo size 1000,500 noenhanced
set output out
set xlabel 'x1 [m]'
set ylabel 'x2 [m]'
set title 'Free surface of the corn every 100 mm of travel (seed fig. 6.30): '.name
set key outside right
set xrange [x0:x0 + 1.2]
set yrange [0.15:0.55]
set grid
set size ratio -1
plot for [k=0:n-1] data index k using 1:2 with lines lw 2 title sprintf('%d mm', 100 * (k + 1))
