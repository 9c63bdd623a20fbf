#!/usr/bin/env python3
"""One cylinder-collapse run (3D quarter or axisymmetric): finished (1/0), last time, front
R_inf [m] (where the deposit, binned by the distance r from the axis in cells, becomes thinner
than R0 / 10), runout (R_inf - R0)/R0, H_inf [m] (the highest particle within 0.02 m of the
axis), kinetic energy at the end over its largest value, particles, steps, wall seconds.
Writes <run>/deposit.dat (r height of the last state)."""
import math
import os
import sys
sys.path.insert(0, os.path.join(os.environ['GPIC_DIR'], 'etc', 'python'))
from gpicdat import cell_size, deposit_front, last_state, read_columns, run_status, write_deposit

d = sys.argv[1]
R0 = 0.1
finished, particles, steps, wall = run_status(d)
last, a = last_state(d)
rs = [math.hypot(p[0], p[2]) for p in a['Points']]  # z = 0 in the axisymmetric plane
ys = [p[1] for p in a['Points']]
write_deposit(d, rs, ys)
h = cell_size(d)
front = deposit_front(rs, ys, h, 0.1 * R0)
top = max(y for r, y in zip(rs, ys) if r < 0.02)
Ek = read_columns(os.path.join(d, 'postProcessing', 'motion', '0', 'bodyMotion.dat'))['Ek']
print(finished, last, '%.4f' % front, '%.3f' % ((front - R0) / R0), '%.4f' % top,
      '%.2e' % (Ek[-1] / max(Ek)), particles, steps, '%.1f' % wall)
