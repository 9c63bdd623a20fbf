# Left: tau/p of the sheared points against mu(I). Right: the separating point's pressure and
# density, step by step, with the critical density rhoC.
set terminal pngcairo size 1200,500
set output 'muI.png'
set multiplot layout 1,2
muS = 0.3819; mu2 = 0.6435; I0 = 0.278
mu(I) = muS + (mu2 - muS) / (I0 / I + 1)
set logscale x
set xrange [1e-3:10]
set yrange [0.35:0.66]
set xlabel 'I [-]'
set ylabel 'tau / p [-]'
set key bottom right
set grid
set title 'muI, glass beads: steady shear at set rates'
plot mu(x) with lines lw 2 lc rgb '#1f77b4' title 'mu(I), Jop et al. 2006', \
     'muI.dat' using 2:3 with points pt 7 ps 1.5 lc rgb '#d62728' title 'picMaterialTest'
unset logscale x
set autoscale
set xlabel 'step (out, then back)'
set ylabel 'p [kPa]'
set y2label 'm/V [kg/m^3]'
set y2tics
set ytics nomirror
set key top left
set title 'Separation and re-forming'
plot 'separation.dat' using 1:3 with lines lw 2 lc rgb '#d62728' title 'p', \
     'separation.dat' using 1:2 axes x1y2 with lines lw 2 lc rgb '#1f77b4' title 'm/V', \
     1485 axes x1y2 with lines dt 2 lc rgb '#1f77b4' title 'rhoC'
unset multiplot
