# The velocity profiles of the runs against Bagnold's (written by Allrun: profile-theta*.dat).
set terminal pngcairo size 900,600
set output 'profile.png'
set xlabel 'u [m/s]'
set ylabel 'y [m] (height above the bed)'
set key top left
set grid
set title 'Glass beads (muI) down a rough slope: the middle of the layer against Bagnold'
files = system('ls profile-theta*.dat')
plot for [f in files] f using 3:1 with lines lw 2 title sprintf('Bagnold, %s', f[9:strlen(f)-4]), \
     for [f in files] f using 2:1 with points pt 7 title sprintf('muI, %s', f[9:strlen(f)-4])
