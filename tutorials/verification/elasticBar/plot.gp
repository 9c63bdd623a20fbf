# Headline curve and error against run time (called by Allrun with finest='...').
set terminal pngcairo size 900,600
set output 'bar.png'
set xlabel 'time [s]'
set ylabel 'centre-of-mass velocity [m/s]'
set title 'Elastic bar, first mode: uGIMP on the finest grid against the exact solution'
plot finest using 1:3 with lines lw 2 title 'exact (2 v0/pi) cos(omega t)', \
     finest using 1:2 with points pt 7 ps 0.4 title 'granular-pic'

set output 'error.png'
set logscale xy
set xlabel 'wall time [s]'
set ylabel 'max error / amplitude'
set title 'Elastic bar: error against run time (ladder of resolutions)'
plot 'errors.dat' using (strcol(1) eq 'uGIMP' ? $5 : NaN):6 with linespoints pt 7 title 'uGIMP', \
     'errors.dat' using (strcol(1) eq 'quadraticBSpline' ? $5 : NaN):6 with linespoints pt 9 title 'quadraticBSpline', \
     'errors.dat' using (strcol(1) eq 'bilinear' ? $5 : NaN):6 with linespoints pt 5 title 'bilinear (seed)'
