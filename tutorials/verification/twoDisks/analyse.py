#!/usr/bin/env python3
"""Seed case 4.4 measures: energy gain and dissipation (seed table 4.3) and the momentum
of the upper-left disk after separation (seed fig. 4.18), from bodyMotion.dat.

Prints: max gain [%], max dissipation [%] of the total energy (kinetic + stress work)
relative to its start, and the change of |x1 momentum| of the upper-left disk at the end
relative to the start [%]. With -series writes time, Ek, Es, E, px to series.dat.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from gpicdat import read_columns  # noqa: E402

case = sys.argv[1]
col = read_columns(os.path.join(case, 'postProcessing/motion/0/bodyMotion.dat'))
E0 = col['E'][0]
gain = max(0.0, max(col['E']) - E0) / E0 * 100
loss = max(0.0, E0 - min(col['E'])) / E0 * 100
px = col['upperLeft:px']
momentum = (abs(px[-1]) - abs(px[0])) / abs(px[0]) * 100
print(f'{gain:.4g} {loss:.4g} {momentum:.4g}')
if '-series' in sys.argv:
    with open(os.path.join(case, 'series.dat'), 'w') as f:
        f.write('# time Ek Es E px_upperLeft\n')
        for row in zip(col['time'], col['Ek'], col['Es'], col['E'], px):
            f.write(' '.join(str(v) for v in row) + '\n')
