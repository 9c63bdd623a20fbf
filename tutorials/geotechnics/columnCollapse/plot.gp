# The deposit of the first run of the ladder (dir set by Allrun).
set terminal pngcairo size 900,400
set output 'deposit.png'
set size ratio -1
set xlabel 'x1 [m]'
set ylabel 'x2 [m]'
set title 'column collapse: the deposit at rest ('.dir.')'
plot dir.'/deposit.dat' using 1:2 with dots lc rgb '#8B5A2B' notitle
