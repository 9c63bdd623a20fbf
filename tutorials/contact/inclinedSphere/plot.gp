# Centre displacement of the three seed cases against eq. 4.3.1, and the stick case's error
# against wall time over the mesh ladder (called by Allrun with finest='...').
set terminal pngcairo size 900,600
set output 'displacement.png'
set xlabel 'time [s]'
set ylabel 'centre displacement along the plane x1 [m]'
set title 'Sphere on an incline (seed 4.3 in 3D, half model): computed (points) against the rigid ball (lines)'
set key top left
plot 'ladder/slip60-8/series.dat' using 1:3 with lines lw 2 lc 1 title '60 deg, mu 0.3 (slip), exact', \
     'ladder/slip60-8/series.dat' every 10 using 1:2 with points pt 7 lc 1 title '8 cells across', \
     'ladder/slip30-8/series.dat' using 1:3 with lines lw 2 lc 2 title '30 deg, mu 0.1 (slip), exact', \
     'ladder/slip30-8/series.dat' every 10 using 1:2 with points pt 7 lc 2 title '8 cells across', \
     'ladder/stick-8/series.dat' using 1:3 with lines lw 2 lc 3 title '60 deg, mu 0.9 (stick), exact', \
     'ladder/stick-8/series.dat' every 10 using 1:2 with points pt 7 lc 3 title '8 cells across', \
     finest every 10 using 1:2 with points pt 5 lc 4 title 'stick, finest mesh'

set output 'error.png'
set logscale xy
set xlabel 'wall time [s]'
set ylabel '|error of x1 at 0.3 s| [%]'
set title 'Rolling sphere (60 deg, mu 0.9): error against run time (labels: cells across the sphere)'
set key top right
plot 'errors.dat' using (strcol(1) eq 'stick' ? $6 : NaN):(abs($8)) with linespoints pt 7 lw 2 title 'granular-pic', \
     'errors.dat' using (strcol(1) eq 'stick' ? $6 : NaN):(abs($8)):3 with labels offset 0,1 notitle
