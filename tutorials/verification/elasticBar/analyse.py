#!/usr/bin/env python3
"""Error of the elastic bar against the exact first mode.

Centre-of-mass velocity of a clamped-free bar vibrating in its first mode:
    v_c(t) = (2 v0 / pi) cos(omega t),  omega = pi c / (2 L),  c = sqrt(E / rho).
Prints the largest |v_c - exact| over the run relative to the amplitude 2 v0 / pi;
with -series also writes time, computed and exact v_c to series.dat in the case.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from gpicdat import read_columns  # noqa: E402

L, E, RHO, V0 = 25.0, 100.0, 1.0, 0.1
OMEGA = math.pi * math.sqrt(E / RHO) / (2 * L)
AMPLITUDE = 2 * V0 / math.pi

case = sys.argv[1]
col = read_columns(os.path.join(case, 'postProcessing/motion/0/bodyMotion.dat'))
exact = [AMPLITUDE * math.cos(OMEGA * t) for t in col['time']]
print(max(abs(v - e) for v, e in zip(col['bar:vx'], exact)) / AMPLITUDE)
if '-series' in sys.argv:
    with open(os.path.join(case, 'series.dat'), 'w') as f:
        f.write('# time vc_computed vc_exact\n')
        for t, v, e in zip(col['time'], col['bar:vx'], exact):
            f.write(f'{t} {v} {e}\n')
