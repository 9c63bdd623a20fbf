# The 3D dragline bucket (seed 6.2.6 at the rig's width): runs='series-<driver>-<dx>.dat ...'
# (given by Allrun; each run's plane twin in series-plane-<driver>-<dx>.dat, N/m).
set terminal pngcairo size 900,650 noenhanced
set output 'force.png'
set xlabel 'bucket travel x1 [mm]'
set ylabel 'draft force F_x1 of the bucket on the corn [N]  (the rig, 0.2 m wide)'
set title "Dragline bucket at the rig's width (seed 6.2.6, fig. 6.25): 3D STL bucket and the plane bucket x 0.2 m\nshaded: the seed's bounds on the measured force up to 600 mm (20 ... 250 N)"
set key outside bottom center horizontal maxrows 3
set xrange [0:*]
set yrange [0:300]
set object 1 rectangle from first 0, first 20 to first 600, first 250 behind fc rgb '#ffe0e0' fs solid noborder
plot NaN with boxes fs solid fc rgb '#ffe0e0' title 'measured, up to 600 mm: 20 ... 250 N', \
     for [r in runs] r using 1:2 with lines lw 1 title '3D '.r[8:strlen(r)-4], \
     for [r in runs] 'series-plane-'.r[8:] using 1:($2 * 0.2) with lines lw 1 dt 2 title 'plane '.r[8:strlen(r)-4]

set output 'parts.png'
unset object 1
set ylabel 'draft force F_x1 [N]'
set yrange [*:*]
set title 'Dragline bucket: the draft force on each part of the STL (the first run)'
first = word(runs, 1)
parts = system("sed -n 2p ".first." | awk '{for (k = 4; k < NF; ++k) { sub(/_N$/, \"\", $k); printf \"%s \", $k } }'")
plot for [k = 1:words(parts)] first using 1:(column(k + 2)) with lines lw 1 title word(parts, k), \
     first using 1:2 with lines lw 2 lc rgb 'black' title 'the whole bucket'

set output 'fill.png'
set ylabel 'corn in the bucket [kg]'
set title "Dragline bucket: the corn it carries (toolFill over its inside) against travel"
plot for [r in runs] r using 1:(column(words(parts) + 3)) with lines lw 2 title r[8:strlen(r)-4]
