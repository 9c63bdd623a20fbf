#!/usr/bin/env python3
"""Penetration of the steel disk into the aluminium target (seed 4.2, fig. 4.3).

The disk starts tangent to the target's top surface, so its penetration depth is the
downward displacement of its centre of mass, y(t) = y_c(0) - y_c(t) (the disk stays nearly
rigid: its lowest point moves with its centre). Prints, in mm and %:
    final depth y(t_end), largest depth, error of the final depth against the seed's 19 mm,
    largest von Mises stress in the target over the written times / sigmaY.
With -series writes time [us] and y [mm] to series.dat in the case.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from gpicdat import read_columns, read_particles  # noqa: E402

SEED_DEPTH, SIGMA_Y = 19.0, 300e6  # mm, Pa

case = sys.argv[1]
col = read_columns(os.path.join(case, 'postProcessing/motion/0/bodyMotion.dat'))
depth = [(col['disk:y'][0] - y) * 1e3 for y in col['disk:y']]

von_mises = 0.0
for d in os.listdir(case):
    path = os.path.join(case, d, 'particles.vtp')
    if os.path.isfile(path):
        part = read_particles(path)
        target = [k for k, b in enumerate(part['body']) if b == 0]  # the first body
        von_mises = max([von_mises] + [part['vonMisesStress'][k] for k in target])

error = (depth[-1] - SEED_DEPTH) / SEED_DEPTH * 100
print(f'{depth[-1]:.3f} {max(depth):.3f} {error:.2f} {von_mises / SIGMA_Y:.5f}')
if '-series' in sys.argv:
    with open(os.path.join(case, 'series.dat'), 'w') as f:
        f.write('# time_us depth_mm\n')
        for t, y in zip(col['time'], depth):
            f.write(f'{t * 1e6:.4f} {y:.5f}\n')
