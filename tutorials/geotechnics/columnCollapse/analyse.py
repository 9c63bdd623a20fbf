#!/usr/bin/env python3
"""One column-collapse run: finished (1/0), last time, front L_inf [m] (where the deposit
becomes thinner than L0 / 10: the film of single particles beyond it is not resolved), runout
(L_inf - L0)/L0,
H_inf [m] (the highest particle within 0.02 m of the wall), kinetic energy at the end over its
largest value, particles, steps, wall seconds. Writes <run>/deposit.dat (x y of the last state)."""
import os
import sys
sys.path.insert(0, os.path.join(os.environ['GPIC_DIR'], 'etc', 'python'))
from gpicdat import cell_size, deposit_front, last_state, read_columns, run_status, write_deposit

d = sys.argv[1]
L0 = 0.1
finished, particles, steps, wall = run_status(d)
last, a = last_state(d)
xs = [p[0] for p in a['Points']]
ys = [p[1] for p in a['Points']]
write_deposit(d, xs, ys)
h = cell_size(d)
front = deposit_front(xs, ys, h, 0.1 * L0)
top = max(y for x, y in zip(xs, ys) if x < 0.02)
Ek = read_columns(os.path.join(d, 'postProcessing', 'motion', '0', 'bodyMotion.dat'))['Ek']
print(finished, last, '%.4f' % front, '%.3f' % ((front - L0) / L0), '%.4f' % top,
      '%.2e' % (Ek[-1] / max(Ek)), particles, steps, '%.1f' % wall)
