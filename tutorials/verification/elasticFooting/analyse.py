#!/usr/bin/env python3
"""Principal stresses under the strip footing against Poulos & Davis (seed eqs. 4.8.1-4.8.2).

A strip of half-width b loaded by P on a weightless elastic half-space; at a point that sees
the strip under the angle beta (compression positive)
    sigma1 = (P/pi) (beta + sin beta),   sigma3 = (P/pi) (beta - sin beta),
on the centre line beta = 2 atan(b/z). The particles of the first column (next to the
symmetry plane) are compared at their own positions (x1, z) with
    beta = atan((x1 + b)/z) - atan((x1 - b)/z).
A case with a rigid footing (constant/rigidBodies, `Allrun -rigid`) is compared with the
rigid smooth strip instead: Sadowsky's contact pressure p(s) = Q / (pi sqrt(b^2 - s^2)),
Q = 2 P b (Johnson 1985, "Contact Mechanics", eq. 2.64), summed as Flamant line loads
(eq. 2.15). Near the surface it differs from the uniform pressure (sigma1 at z = 0.5 m:
68 against 96 kPa); below z = 3 m the two agree within 1.3 % of P.
Depth z is measured from the top of the model (the top of the particle domains). Prints
the errors max |numerical - closed form| / P [%] over the depths 0.5 <= z <= 6 m at the last
time written: of both stresses, of sigma1 and of sigma3. With -series writes z, numerical and
closed-form sigma1 and sigma3 [kPa] and the centre-line curves to series.dat in the case.
"""
import glob
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from gpicdat import read_particles  # noqa: E402

P, B = 100e3, 1.0  # footing pressure [Pa] and half-width [m] (constant/loads)
Z_MIN, Z_MAX = 0.5, 6.0


def closed_form(x1, z):
    """(sigma1, sigma3) [Pa], compression positive, at (x1, depth z)."""
    beta = math.atan2(x1 + B, z) - math.atan2(x1 - B, z)
    return P / math.pi * (beta + math.sin(beta)), P / math.pi * (beta - math.sin(beta))


def rigid_strip(x1, z, n=2000):
    """(sigma1, sigma3) [Pa], compression positive, under the rigid smooth strip."""
    s11 = s22 = s12 = 0.0
    for k in range(n):  # s = b sin(theta): p ds = Q dtheta / pi, each strip a line load
        s = B * math.sin(-math.pi / 2 + (k + 0.5) * math.pi / n)
        dx = x1 - s
        c = 2 * (2 * P * B / n) / (math.pi * (dx * dx + z * z) ** 2)
        s22, s11, s12 = s22 + c * z ** 3, s11 + c * dx * dx * z, s12 + c * dx * z * z
    centre, radius = 0.5 * (s11 + s22), math.hypot(0.5 * (s11 - s22), s12)
    return centre + radius, centre - radius


def principal(s):
    """(sigma1, sigma3) compression positive from a row-major 3x3 tension-positive stress."""
    s11, s12, s22 = -s[0], -s[1], -s[4]
    centre, radius = 0.5 * (s11 + s22), math.hypot(0.5 * (s11 - s22), s12)
    return centre + radius, centre - radius


def last_time(case):
    times = [d for d in os.listdir(case) if os.path.isfile(os.path.join(case, d, 'particles.vtp'))]
    return max(times, key=float)


case = sys.argv[1]
if os.path.exists(os.path.join(case, 'constant', 'rigidBodies')):
    closed_form = rigid_strip
part = read_particles(os.path.join(case, last_time(case), 'particles.vtp'))
soil = [k for k, b in enumerate(part['body']) if b == 0]  # the first body (a footing may follow)
x0 = [part['initialPosition'][k] for k in soil]
surface = max(x0[i][1] + part['halfSize'][k][1] for i, k in enumerate(soil))
first = min(x[0] for x in x0)
rows = []
for x, s in zip(x0, (part['stress'][k] for k in soil)):
    if abs(x[0] - first) < 1e-9:
        z = surface - x[1]
        rows.append((z, x[0]) + principal(s) + closed_form(x[0], z))
rows.sort()
compared = [r for r in rows if Z_MIN <= r[0] <= Z_MAX]
error1 = max(abs(r[2] - r[4]) for r in compared) / P * 100
error3 = max(abs(r[3] - r[5]) for r in compared) / P * 100
print(f'{max(error1, error3):.3f} {error1:.3f} {error3:.3f}')
if '-series' in sys.argv:
    with open(os.path.join(case, 'series.dat'), 'w') as f:
        f.write('# z x1 sigma1 sigma3 sigma1_exact sigma3_exact [kPa] at the first-column particles\n')
        for r in rows:
            f.write(f'{r[0]} {r[1]} ' + ' '.join(f'{v / 1e3:.6g}' for v in r[2:]) + '\n')
        f.write('\n\n# z sigma1 sigma3 [kPa] on the centre line x1 = 0 (the closed form)\n')
        for k in range(1, 121):
            z = 0.05 * k
            f.write(f'{z} ' + ' '.join(f'{v / 1e3:.6g}' for v in closed_form(0.0, z)) + '\n')
