# The mass gone against time after the opening, each run with its Beverloo line (written by
# Allrun: series-<geometry>-<model>-H<H>-h<h>.dat, from etc/python/silodischarge.py).
set terminal pngcairo size 1200,550 noenhanced
set output 'mass.png'
set multiplot layout 1,2 title "Glass beads (muI) and mohrCoulomb out of a silo, D = 0.06 and 0.1 m: mass gone, and Beverloo's rate (dashed)"
set xlabel 't after the opening [s]'
set key top left
set grid
do for [geometry in 'plane axisymmetric'] {
    files = system('ls series-'.geometry.'-*.dat 2> /dev/null')
    set ylabel (geometry eq 'plane' ? 'mass gone [kg per m of slot]' : 'mass gone [kg]')
    set title (geometry eq 'plane' ? 'plane silo, a slot' : 'cylindrical silo, a circular orifice')
    plot for [f in files] f using 1:2 with lines lw 2 title f[8:strlen(f)-4], \
         for [f in files] f using 1:3 with lines dt 2 lc rgb 'black' notitle
}
unset multiplot
