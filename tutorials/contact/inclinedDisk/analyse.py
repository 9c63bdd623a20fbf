#!/usr/bin/env python3
"""Seed case 4.3: centre displacement of the disk along the plane against eq. 4.3.1.

Rigid disk rolling down a plane at theta with Coulomb friction mu:
    x1(t) = g t^2 (sin theta - mu cos theta) / 2   if tan theta > 3 mu (rolls and slips)
    x1(t) = g t^2 sin theta / 3                    otherwise (rolls without slipping)
Usage: analyse.py <case> <theta_deg> <mu> [-series]
Prints the error of x1 at the last time [%] (signed: + ahead of the exact motion) and the
rise of the centre normal to the plane [mm]; with -series writes time, computed and exact
x1 to series.dat in the case.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from gpicdat import read_columns  # noqa: E402

G = 9.81
case, theta, mu = sys.argv[1], math.radians(float(sys.argv[2])), float(sys.argv[3])
slips = math.tan(theta) > 3 * mu


def exact(t):
    if slips:
        return 0.5 * G * t * t * (math.sin(theta) - mu * math.cos(theta))
    return G * t * t * math.sin(theta) / 3


col = read_columns(os.path.join(case, 'postProcessing/motion/0/bodyMotion.dat'))
x = [v - col['disk:x'][0] for v in col['disk:x']]
t = col['time']
rise = (col['disk:y'][-1] - col['disk:y'][0]) * 1000
print(f'{(x[-1] - exact(t[-1])) / exact(t[-1]) * 100:.4f} {rise:.2f}')
if '-series' in sys.argv:
    with open(os.path.join(case, 'series.dat'), 'w') as f:
        f.write('# time x1_computed x1_exact\n')
        for ti, xi in zip(t, x):
            f.write(f'{ti} {xi} {exact(ti)}\n')
