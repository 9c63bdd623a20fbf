# -sigma22 against -eps22 for both dilatancy angles, computed and closed form (seed Fig. 4.25).
set terminal pngcairo size 900,600
set output 'oedometer.png'
set xlabel '-eps22 [-]'
set ylabel '-sigma22 [MPa]'
set key top left
set grid
set title 'Plane-strain oedometer, Mohr-Coulomb (seed 4.5): material point against appendix H.5.4'
plot 'series.dat' using 1:3 with lines lw 2 lc rgb '#1f77b4' title 'closed form, psi = 10', \
     'series.dat' every 100 using 1:2 with points pt 7 lc rgb '#1f77b4' title 'picMaterialTest, psi = 10', \
     'series.dat' using 1:5 with lines lw 2 lc rgb '#d62728' title 'closed form, psi = 0', \
     'series.dat' every 100 using 1:4 with points pt 5 lc rgb '#d62728' title 'picMaterialTest, psi = 0'
