#!/usr/bin/env python3
"""Seed case 4.3 in 3D: centre displacement of the sphere along the plane against a rigid
sphere's.

A rigid ball (moment of inertia 2/5 m R^2) on a plane at theta with Coulomb friction mu:
    x1(t) = g t^2 (sin theta - mu cos theta) / 2   if tan theta > 7/2 mu (rolls and slips)
    x1(t) = 5/14 g t^2 sin theta                   otherwise (rolls without slipping)
(the disk's eq. 4.3.1 with the ball's inertia: a = g sin theta / (1 + I/(m R^2)) = 5/7 g sin
theta when it sticks, which needs a friction of 2/7 m g sin theta <= mu m g cos theta).
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
slips = math.tan(theta) > 3.5 * mu


def exact(t):
    if slips:
        return 0.5 * G * t * t * (math.sin(theta) - mu * math.cos(theta))
    return 5.0 / 14.0 * G * t * t * math.sin(theta)


col = read_columns(os.path.join(case, 'postProcessing/motion/0/bodyMotion.dat'))
x = [v - col['sphere:x'][0] for v in col['sphere:x']]
t = col['time']
rise = (col['sphere:z'][-1] - col['sphere:z'][0]) * 1000
print(f'{(x[-1] - exact(t[-1])) / exact(t[-1]) * 100:.4f} {rise:.2f}')
if '-series' in sys.argv:
    with open(os.path.join(case, 'series.dat'), 'w') as f:
        f.write('# time x1_computed x1_exact\n')
        for ti, xi in zip(t, x):
            f.write(f'{ti} {xi} {exact(ti)}\n')
