#!/usr/bin/env python3
"""Draft force and shear band of a blade-in-corn case turned on the grid (makeCase.py), in
the rig's own frame (s along the floor, n up), so that a turned run compares with the upright.

Forces: the forces function object gives the force of the corn on the blade in grid axes;
the seed's draft force is that of the blade on the corn along the floor,
    F_x1 = -(F . e_s),  F_x2 = -(F . e_n),
averaged over 15 ... 35 mm of travel (trapezoidal in time, as ../cornBlade/analyse.py).

Shear band (seed fig. 6.15): the particle displacement ratio PDR = |particle displacement| /
blade travel over the written times nearest to 5 and 15 mm of travel. The band is the outer
edge of the zone PDR >= 0.15: in each strip of n one cell high, from the blade's foot to the
surface, the largest s of a particle with PDR >= 0.15. Printed:
    reach: where the edge meets the top strip, s - s_front [m] (Sokolovski: x_s = 2 h);
    angle: the slope of a least-squares line through the edge points [deg from the floor].

Usage: analyse.py <case> <dx>
Prints: F_x1 F_x2 [N/m] reach [m] angle [deg]; writes pdr.dat (s n PDR) and edge.dat (s n).
"""
import glob
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from gpicdat import read_columns, read_particles, window_mean  # noqa: E402


def main():
    case, dx = sys.argv[1], float(sys.argv[2])
    with open(os.path.join(case, 'turn.dat')) as f:
        angle, ox, oy, front, foot, top = [float(v) for v in f.read().split('\n')[1].split()]
    phi = -math.radians(angle)
    es, en = (math.cos(phi), math.sin(phi)), (-math.sin(phi), math.cos(phi))

    def rig(x):  # grid position -> (s, n)
        dxg, dyg = x[0] - ox, x[1] - oy
        return dxg * es[0] + dyg * es[1], dxg * en[0] + dyg * en[1]

    path = glob.glob(os.path.join(case, 'postProcessing', 'forces', '*', 'forces.dat'))[0]
    c = read_columns(path)
    t = c['time']
    travel = [math.hypot(a, b) for a, b in zip(c['blade:dx'], c['blade:dy'])]
    f1 = [-(a * es[0] + b * es[1]) for a, b in zip(c['blade:Fx'], c['blade:Fy'])]
    f2 = [-(a * en[0] + b * en[1]) for a, b in zip(c['blade:Fx'], c['blade:Fy'])]
    keep = [0.015 - 1e-9 <= d <= 0.035 + 1e-9 for d in travel]
    F1, F2 = window_mean(t, f1, keep), window_mean(t, f2, keep)
    if F1 is None:
        sys.exit('analyse.py: no forces over 15 ... 35 mm of travel (is the run complete?)')
    with open(os.path.join(case, 'series.dat'), 'w') as f:
        f.write('# travel_mm Fx1 Fx2 [N/m], in the rig frame\n')
        for d, a, b in zip(travel, f1, f2):
            if d > 0:
                f.write(f'{d * 1e3:.4f} {a:.2f} {b:.2f}\n')

    # Written states and the blade's travel at each.
    states = []
    for d in glob.glob(os.path.join(case, '[0-9]*')):
        if re.fullmatch(r'[0-9.e+-]+', os.path.basename(d)) and os.path.isfile(os.path.join(d, 'particles.vtp')):
            states.append((float(os.path.basename(d)), d))
    states.sort()

    def blade_travel(part):
        u = [x for b, x in zip(part['body'], part['displacement']) if b == 1]
        return math.hypot(sum(x[0] for x in u) / len(u), sum(x[1] for x in u) / len(u))

    loaded = [(blade_travel(p), p) for p in (read_particles(os.path.join(d, 'particles.vtp')) for _, d in states[-30:])]
    a = min(loaded, key=lambda s: abs(s[0] - 0.005))
    b = min(loaded, key=lambda s: abs(s[0] - 0.015))
    before = {i: x for i, x in zip(a[1]['id'], a[1]['Points'])}
    moved = b[0] - a[0]
    shift = front + b[0]  # the blade's front face now, in s
    rows = []
    for i, body, x in zip(b[1]['id'], b[1]['body'], b[1]['Points']):
        if body == 0 and i in before:
            x0 = before[i]
            s, n = rig(x)
            rows.append((s - shift, n, math.hypot(x[0] - x0[0], x[1] - x0[1]) / moved))
    with open(os.path.join(case, 'pdr.dat'), 'w') as f:
        f.write(f'# PDR over blade travel {a[0] * 1e3:.1f} ... {b[0] * 1e3:.1f} mm; s from the blade front, n up\n')
        f.write('# s n PDR\n')
        for r in rows:
            f.write(f'{r[0]:.5f} {r[1]:.5f} {r[2]:.4f}\n')
    edge = {}
    for s, n, p in rows:
        k = math.floor((n - foot) / dx)
        if p >= 0.15 and 0 <= k:
            edge[k] = max(edge.get(k, -1.0), s)
    strips = sorted(k for k in edge if (foot + (k + 1) * dx) <= top + 1e-9)
    points = [(edge[k], foot + (k + 0.5) * dx) for k in strips]
    with open(os.path.join(case, 'edge.dat'), 'w') as f:
        f.write('# outer edge of PDR >= 0.15: s from the blade front, n [m]\n')
        for s, n in points:
            f.write(f'{s:.5f} {n:.5f}\n')
    reach = points[-1][0] if points else float('nan')
    if len(points) >= 2:
        ms = sum(p[0] for p in points) / len(points)
        mn = sum(p[1] for p in points) / len(points)
        sxx = sum((p[0] - ms) ** 2 for p in points)
        sxy = sum((p[0] - ms) * (p[1] - mn) for p in points)
        slope = math.degrees(math.atan2(sxy, sxx))
    else:
        slope = float('nan')
    print(f'{F1:.1f} {F2:.1f} {reach:.3f} {slope:.1f}')


main()
