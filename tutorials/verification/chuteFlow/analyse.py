#!/usr/bin/env python3
"""One chute run: the velocity profile in the middle of the layer against Bagnold's.

Steady uniform flow of depth h down a slope theta, y normal to the bed, p = -tr(sigma)/3
(compression positive) and rho = m/V the bulk density: the momentum balance gives
sigma_yy = -rho g cos(theta) (h - y) and sigma_xy = rho g sin(theta) (h - y). The plastic flow
is a pure shear along the deviator, so in the steady state the normal stresses are equal (the
deviator's normal part relaxes; the Jaumann rotation leaves differences of order tau^2/G):
p = rho g cos(theta) (h - y) and tau = sqrt(J2) = sigma_xy, so tau/p = tan(theta) = mu(I) at
every depth, I = I_theta = I0 (tan(theta) - muS) / (mu2 - tan(theta)), and
gammaDot = (I_theta / d) sqrt(p / rhoS) = (I_theta / d) sqrt(phi g cos(theta) (h - y)) with
phi = rho / rhoS (the solid fraction, for our p and rho). Integrated from the no-slip bed:

    u(y) = (2/3) (I_theta / d) sqrt(phi g cos(theta)) (h^(3/2) - (h - y)^(3/2)).

Below atan(muS) there is no steady flow: the layer stays at rest.

The particles compared are those that started within 0.1 m of the middle of the layer, far
from its ends (the disturbances from the upstream end and the front travel about
sqrt(g h cos(theta)) = 0.67 m/s into it). They are binned by height in rows of half a cell
(two particles a cell); each row's mean velocity is compared with u at its mean height.

Prints: finished, particles, steps, wall [s], u_top ours, u_top Bagnold [m/s], the error of the
top row and the largest row error, both in % of Bagnold's surface velocity u(h) (below
atan(muS) both are the largest row speed in mm/s instead, Bagnold 0), and the change of
u_top over the last written interval in %.
With -profile FILE writes y, u ours, u Bagnold of the rows.
"""
import math
import os
import re
import sys
sys.path.insert(0, os.path.join(os.environ['GPIC_DIR'], 'etc', 'python'))
from gpicdat import read_particles, run_status

MU_S, MU_2, I_0, RHO_S = 0.3819, 0.6435, 0.278, 2450.0
G = 9.81

case = sys.argv[1]
theta = math.radians(float(sys.argv[2]))
constant = lambda name: open(os.path.join(case, 'constant', name)).read()
d = float(re.search(r'^\s*d\s+([0-9.eE+-]+)\s*;', constant('materials'), re.M).group(1))
length, h = map(float, re.search(r'max \(([0-9.eE+-]+) ([0-9.eE+-]+)\)', constant('bodies')).groups())
cell = float(re.search(r'cellSize\s+([0-9.eE+-]+);', constant('grid')).group(1))


def rows(time):
    """(mean y, mean u, mean m/V) of each half-cell row of the middle particles at `time`."""
    a = read_particles(os.path.join(case, time, 'particles.vtp'))
    middle = [i for i, p in enumerate(a['initialPosition']) if abs(p[0] - length / 2) <= 0.1]
    binned = {}
    for i in middle:
        binned.setdefault(int(a['Points'][i][1] / (cell / 2)), []).append(i)
    out = []
    for b in sorted(binned):
        k = binned[b]
        out.append((sum(a['Points'][i][1] for i in k) / len(k), sum(a['velocity'][i][0] for i in k) / len(k),
                    sum(a['mass'][i] / a['volume'][i] for i in k) / len(k)))
    return out


times = sorted((t for t in os.listdir(case) if t[0].isdigit()
                and os.path.isfile(os.path.join(case, t, 'particles.vtp'))), key=float)
finished, particles, steps, wall = run_status(case)
last, before = rows(times[-1]), rows(times[-2])
rho = sum(r[2] for r in last) / len(last)
tan = math.tan(theta)
if tan > MU_S:
    I_theta = I_0 * (tan - MU_S) / (MU_2 - tan)
    scale = (2.0 / 3.0) * (I_theta / d) * math.sqrt(rho / RHO_S * G * math.cos(theta))
    bagnold = lambda y: scale * (h ** 1.5 - max(h - y, 0.0) ** 1.5)
else:
    bagnold = lambda y: 0.0
top_y, top_u = last[-1][0], last[-1][1]
if tan > MU_S:
    surface = bagnold(h)
    row_errors = [abs(u - bagnold(y)) / surface for y, u, _ in last]
    top_error = 100 * (top_u - bagnold(top_y)) / surface
    worst = 100 * max(row_errors)
else:
    top_error = 1e3 * max(abs(u) for _, u, _ in last)  # mm/s: at rest
    worst = top_error
drift = 100 * (top_u - before[-1][1]) / max(abs(top_u), 1e-12)
print(finished, particles, steps, '%.1f' % wall, '%.4f' % top_u, '%.4f' % bagnold(top_y),
      '%.2f' % top_error, '%.2f' % worst, '%.2f' % drift)

if '-profile' in sys.argv:
    with open(sys.argv[sys.argv.index('-profile') + 1], 'w') as f:
        f.write('# y [m] | u ours | u Bagnold [m/s], theta %g deg, t %s s\n' % (math.degrees(theta), times[-1]))
        for y, u, _ in last:
            f.write('%.6g %.6g %.6g\n' % (y, u, bagnold(y)))
