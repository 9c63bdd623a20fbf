# The error of each solid's filled volume against picInit's wall time over the ladder.
set terminal pngcairo size 900,650 noenhanced
set output 'error.png'
set logscale xy
set xlabel 'wall time of picInit [s]'
set ylabel 'volume error [%]'
set title 'Bodies from STL surfaces: filled volume against the exact solid'
set key top right
plot '< grep "^sphere" errors.dat' using 4:5 with linespoints pt 7 lw 2 title 'sphere', \
     '< grep "^box" errors.dat' using 4:5 with linespoints pt 5 lw 2 title 'box turned 30 deg', \
     '< grep "^torus" errors.dat' using 4:5 with linespoints pt 9 lw 2 title 'torus'
