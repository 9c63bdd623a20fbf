#!/usr/bin/env python3
"""One column-collapse run: finished (1/0), last time, front L_inf [m] (where the deposit
becomes thinner than L0 / 10: the film of single particles beyond it is not resolved), runout
(L_inf - L0)/L0 and Lube's, H_inf/L0 (H_inf: the highest particle within 0.02 m of the wall)
and Lube's, kinetic energy at the end over its largest value, particles, steps, wall seconds.
Writes <run>/deposit.dat (x y of the last state).

Lube, Huppert, Sparks & Freundt (2005, Phys. Rev. E 72, 041301), two-dimensional collapses of
dry granular columns in a channel, a = H/L0:
    runout (L_inf - L0)/L0 = 1.2 a (a < 2.3), 1.9 a^(2/3) (a > 2.3)
    final height H_inf/L0 = a (a < 1.15: the column's top is left standing), a^(2/5) above
      (H_inf/H = a^(-3/5), the exponent Balmforth & Kerswell 2005, J. Fluid Mech. 538, also
      find in wide channels, H/h_inf ~ a^0.6)
Usage: analyse.py <run> <a>"""
import os
import sys
sys.path.insert(0, os.path.join(os.environ['GPIC_DIR'], 'etc', 'python'))
from gpicdat import cell_size, deposit_front, last_state, read_columns, run_status, write_deposit


def lube_runout(a):
    return 1.2 * a if a < 2.3 else 1.9 * a ** (2.0 / 3.0)


def lube_height(a):
    return a if a < 1.15 else a ** 0.4


d, a = sys.argv[1], float(sys.argv[2])
L0 = 0.1
finished, particles, steps, wall = run_status(d)
last, state = last_state(d)
xs = [p[0] for p in state['Points']]
ys = [p[1] for p in state['Points']]
write_deposit(d, xs, ys)
h = cell_size(d)
front = deposit_front(xs, ys, h, 0.1 * L0)
top = max(y for x, y in zip(xs, ys) if x < 0.02)
Ek = read_columns(os.path.join(d, 'postProcessing', 'motion', '0', 'bodyMotion.dat'))['Ek']
print(finished, last, '%.4f' % front, '%.3f' % ((front - L0) / L0), '%.3f' % lube_runout(a),
      '%.3f' % (top / L0), '%.3f' % lube_height(a), '%.2e' % (Ek[-1] / max(Ek)), particles, steps, '%.1f' % wall)
