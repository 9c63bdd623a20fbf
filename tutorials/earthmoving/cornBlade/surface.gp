# Free surface of the corn in front of the blade after 100, 200, 300 and 400 mm of travel
# (h = 0.2 m; seed figs. 6.9 and 6.11), one colour per travel and one dash per run.
# Given: files (surface-<run>.dat of analyse.py -surface, one block per travel), out.
set terminal pngcairo size 1000,450 noenhanced
set output out
set xlabel 'x1 [m]'
set ylabel 'x2 [m]'
set title 'Free surface of the corn after 100 ... 400 mm of blade travel (seed figs. 6.9, 6.11)'
set key outside right
set grid
set xrange [0:1.2]
n = words(files)
plot for [f=1:n] for [k=0:3] word(files, f) index k using 1:2 with lines lw 2 lc k + 1 dt f \
     title sprintf('%s, %d mm', word(files, f)[9:strlen(word(files, f)) - 4], 100 * (k + 1))
