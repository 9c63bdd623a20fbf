# Principal stresses under the footing centre against Poulos & Davis (the run in the
# directory run='...', given by Allrun), and the error of the ladder against run time.
# ref: the closed form's name (Allrun: 'rigid strip' for the rigid footing).
if (!exists('ref')) ref = 'Poulos & Davis'
set terminal pngcairo size 900,650 noenhanced
set output 'stress.png'
shown = run.'/series.dat'
set xlabel 'principal stress [kPa], compression positive'
set ylabel 'depth below the surface z [m]'
set title 'Elastic strip footing (seed 4.8), P = 100 kPa, b = 1 m: first-column particles ('.(run eq '.' ? 'the case' : run).')'
set yrange [6:0]
set xrange [-10:110]
set key bottom right
plot shown index 1 using 2:1 with lines lw 2 lc rgb 'blue' title 'sigma1, '.ref.' (x1 = 0)', \
     shown index 1 using 3:1 with lines lw 2 lc rgb 'red' title 'sigma3, '.ref.' (x1 = 0)', \
     shown index 0 using 3:1 with points pt 7 ps 0.8 lc rgb 'blue' title 'sigma1, granular-pic', \
     shown index 0 using 4:1 with points pt 5 ps 0.8 lc rgb 'red' title 'sigma3, granular-pic'

set output 'error.png'
set xrange [*:*]
set yrange [*:*] noreverse
set logscale xy
set xlabel 'wall time [s]'
set ylabel 'max |error| / P [%], 0.5 <= z <= 6 m'
set title 'Elastic strip footing: error against run time (seed: within 6 %)'
set key top right
plot for [m in 'seed wide rigid'] 'errors.dat' using (strcol(1) eq m ? $5 : NaN):6 with linespoints pt 7 \
         title (m eq 'seed' ? '25 m model (seed)' : m eq 'wide' ? '50 m model' : 'rigid footing, 25 m'), \
     6 with lines dt 2 lc rgb 'black' title 'seed accuracy (6 %)', \
     3 with lines dt 3 lc rgb 'gray40' title '3 %'
