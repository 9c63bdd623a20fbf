# Plots of Allrun (called with materials='elastic ...').
set terminal pngcairo size 900,600
set grid

set output 'force.png'
set title 'Plunger oedometer: plunger force and sample stress (seed Fig. 4.26), dt = 1e-6 s'
set xlabel 'time [ms]'
set ylabel 'force [MN/m], stress x 1 m [MN/m]'
set key top left
plot for [m in materials] 'runs/'.m.'-1e-6/series.dat' using ($1*1e3):($6/1e6) with lines lw 2 title m.': -sigma22 x 1 m', \
     for [m in materials] 'runs/'.m.'-1e-6/series.dat' using ($1*1e3):($5/1e6) with points pt 7 ps 0.8 title m.': plunger force F'

set output 'stressPath.png'
set title 'Plunger oedometer: stress path against the closed form of seed H.5.4 (Fig. 4.25)'
set xlabel '-eps22 [-]'
set ylabel '-sigma22 [MPa]'
plot for [m in materials] 'runs/'.m.'-1e-6/series.dat' using 2:($4/1e6) with lines lw 2 title m.': closed form', \
     for [m in materials] 'runs/'.m.'-1e-6/series.dat' using 2:($3/1e6) with points pt 7 ps 0.8 title m.': granular-pic'

set output 'error.png'
set title 'Plunger oedometer: errors against run time (dt ladder)'
set logscale xy
set xlabel 'wall time [s]'
set ylabel 'relative error'
set key top right
plot for [m in materials] 'errors.dat' using (strcol(1) eq m ? $5 : NaN):6 with linespoints pt 7 title m.': stress path', \
     for [m in materials] 'errors.dat' using (strcol(1) eq m ? $5 : NaN):7 with linespoints pt 5 title m.': force vs sigma22 x 1 m'
