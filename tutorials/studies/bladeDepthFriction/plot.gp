# The study's front-face forces against depth for each blade friction, with Sokolovski's
# (compare.py writes compare.dat and sokolovski.dat), and the error against wall time.
set terminal pngcairo size 900,650 noenhanced
set key top left

set output 'force.png'
set title 'Blade (seed 4.7) on 40 x 20 cells: front face F_x1, mean over 10 ... 25 mm of travel'
set xlabel 'depth h [m]'
set ylabel 'F_x1 [N/m]'
mus = system("awk '!/^#/ { print $2 }' compare.dat | sort -u | tr '\\n' ' '")
plot for [k=1:words(mus)] 'sokolovski.dat' using 1:(column(k + 1)) with lines lw 2 lc k \
         title 'Sokolovski, mu '.word(mus, k), \
     for [k=1:words(mus)] 'compare.dat' using ($2 == word(mus, k) + 0 ? $1 : NaN):7 \
         with points pt 7 ps 1.5 lc k title 'study, mu '.word(mus, k)

set output 'error.png'
set title 'Front face F_x1 against Sokolovski, and run time'
set xlabel 'wall time [s]'
set ylabel 'error [%]'
plot 'compare.dat' using 5:10 with points pt 7 ps 1.5 title 'front face', \
     'compare.dat' using 5:9 with points pt 6 ps 1.5 title 'whole blade'
