#!/usr/bin/env python3
"""The layered fill's stress against the confined elastic column (seed eqs. 3.3.1-3.3.4).

After the fill and an undamped rest, an elastic column of height H between smooth walls
carries
    sigma22 = -rho g (H - x2),   sigma11 = K0 sigma22,   K0 = nu / (1 - nu) = 0.4286,
whatever K0 its layers entered with (Jaky's 0.5 here): the weight of the layers above reaches
each layer through the elastic, laterally confined response. Prints the base stress (the mean
of the lowest row of particles, at depth H - x2) against rho g (H - x2), the largest errors
over the column in % of rho g H, and writes depth, sigma22, sigma11 and the closed forms [kPa]
to profile.dat. Depth from the initial positions (x0).
"""
import glob
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from gpicdat import read_particles  # noqa: E402

RHO, G, H, NU = 2000.0, 9.81, 2.0, 0.3
K0 = NU / (1 - NU)

case = sys.argv[1] if len(sys.argv) > 1 else '.'
times = [d for d in glob.glob(os.path.join(case, '[0-9]*')) if os.path.isdir(d)]
last = max(times, key=lambda d: float(os.path.basename(d)))
p = read_particles(os.path.join(last, 'particles.vtp'))
x0 = [x[1] for x in p['initialPosition']]
s11 = [s[0] for s in p['stress']]
s22 = [s[4] for s in p['stress']]

rows = sorted(zip(x0, s22, s11))
with open(os.path.join(case, 'profile.dat'), 'w') as f:
    f.write('# depth_m sigma22_kPa sigma11_kPa closedForm22_kPa closedForm11_kPa\n')
    for y, a, b in rows:
        exact = -RHO * G * (H - y)
        f.write('%g %g %g %g %g\n' % (H - y, a / 1e3, b / 1e3, exact / 1e3, K0 * exact / 1e3))

lowest = min(x0)
base = [a for y, a, _ in rows if y == lowest]
exact = -RHO * G * (H - lowest)
err22 = max(abs(a + RHO * G * (H - y)) for y, a, _ in rows) / (RHO * G * H)
err11 = max(abs(b - K0 * a) for y, a, b in rows if H - y >= 0.1) / (RHO * G * H)
print('time %s: %d particles' % (os.path.basename(last), len(x0)))
print('base (x2 = %g m): sigma22 %.3f kPa, rho g (H - x2) %.3f kPa, error %.2f %%'
      % (lowest, sum(base) / len(base) / 1e3, exact / 1e3, 100 * (sum(base) / len(base) - exact) / exact))
print('over the column: max |sigma22 + rho g (H - x2)| %.2f %%, max |sigma11 - K0 sigma22| %.2f %% of rho g H'
      ' (K0 = nu/(1-nu) = %.4f; seed-style bound 2 %%)' % (100 * err22, 100 * err11, K0))
