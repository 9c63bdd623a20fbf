# Shear band of the blade in corn (seed fig. 6.15): the particles whose displacement over a
# 10 mm blade increment is at least 0.15 times the blade's (PDR >= 0.15, dark), from pdr.dat
# (analyse.py -pdr). Given: case, out, name.
set terminal pngcairo size 1000,520 noenhanced
set output out
set size ratio -1
set xlabel 'x1 [m]'
set ylabel 'x2 [m]'
set title 'PDR >= 0.15 (dark): '.name."\n".system("sed -n 1p ".case."/pdr.dat | cut -c3-")
set palette defined (0 '#d9d9d9', 0.1499 '#d9d9d9', 0.15 '#8b0000', 1 'black')
set cbrange [0:1]
set cblabel 'PDR'
set key off
plot case.'/pdr.dat' using 1:2:3 with points pt 5 ps 0.5 lc palette
