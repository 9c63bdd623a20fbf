#!/usr/bin/env python3
"""Mean draft and vertical force per width of a blade run (3D half model or its plane twin).

The forces function object writes the force of the sand on the blade (postProcessing/forces/
*/forces.dat). Per width of the whole blade, the force of the blade on the sand is
    3D half model (blade half-width b = w/2):  F_x1 = -blade:Fx / b,  F_x3 = -blade:Fz / b,
    plane twin (per metre):                    F_x1 = -blade:Fx,      F_x3 = -blade:Fy,
F_x3 < 0: the sand lifts the blade. The mean is the trapezoidal time average over the
samples with d0 <= blade travel <= d1.

The depth h is measured on the case, from the particles picInit made (time 0): the top of the
sand's particle domains less the foot of the blade's, along the vertical (the last axis).
The references at that h, with phi and rho of the material `sand` and mu = tan(delta) of
constant/contactProperties: McKyes & Ali (1977) for the width w (mckyesAli.py) and for plane
strain (w -> infinity: Coulomb's wedge), and Sokolovski's rough wall (picSokolovski).

Usage: analyse.py <case> -w W [-window d0 d1] [-series]
  W: the blade's whole width [m] (ignored for a plane case), d0 d1 [m] (default 0.005 0.010)
Prints: h F_x1 F_x3 McKyes_H McKyes_V McKyes_plane_H Sokolovski_H Sokolovski_V reached_mm reach_m side_%
reach (3D): how far from the mid-plane the sand moved, the largest x2 of the sand's particles
displaced by more than a tenth of the blade's travel in the last time written; side: the
largest displacement of the sand within a cell of the bin's side, in % of the travel (whether
the side felt the blade); '-' in a plane case.
-series writes series.dat in the case: travel [mm], F_x1, F_x3 [N/m].
"""
import math
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gpicdat  # noqa: E402
from gpicdat import case_entries, last_state, read_series, tool_depth, window_mean  # noqa: E402
from mckyesAli import forces as mckyes_ali  # noqa: E402


def sokolovski(h, phi, mu, rho):
    out = subprocess.run(['picSokolovski', '-phi', phi, '-mu', mu, '-rho', rho, '-h', repr(h)],
                         capture_output=True, text=True, check=True).stdout
    row = next(line.split() for line in out.splitlines() if re.match(r'\s*\d+\.\d+\s+\d', line))
    return float(row[2]), float(row[3])


case = sys.argv[1]
w = gpicdat.option(sys.argv, '-w', 1, [None])[0]
d0, d1 = gpicdat.option(sys.argv, '-window', 2, [0.005, 0.010])
c = read_series(case, 'forces', 'forces.dat')
if not c:
    sys.exit(f'analyse.py: no forces in {case}/postProcessing/forces')
threeD = 'blade:Fz' in c
if threeD and w is None:
    sys.exit('analyse.py: a 3D case needs -w <blade width [m]>')
per = 2.0 / w if threeD else 1.0          # the half model carries half the blade
t, travel = c['time'], c['blade:dx']
f1 = [-f * per for f in c['blade:Fx']]
f3 = [-f * per for f in c['blade:Fz' if threeD else 'blade:Fy']]
keep = [d0 - 1e-9 <= d <= d1 + 1e-9 for d in travel]
F1, F3 = window_mean(t, f1, keep), window_mean(t, f3, keep)
if F1 is None:
    sys.exit(f'analyse.py: {case}: no forces in the window {d0 * 1e3:g} ... {d1 * 1e3:g} mm (did the run stop?)')
h = tool_depth(case)
sand = case_entries(os.path.join(case, 'constant', 'materials'), 'sand')
mu = case_entries(os.path.join(case, 'constant', 'contactProperties'), None)['mu']
delta = math.degrees(math.atan(float(mu)))
width = w if threeD else math.inf
_, _, M1, M3 = mckyes_ali(float(sand['phi']), delta, float(sand['rho']), h, width)
_, _, P1, _ = mckyes_ali(float(sand['phi']), delta, float(sand['rho']), h, math.inf)
S1, S3 = sokolovski(h, sand['phi'], mu, sand['rho'])
reach = side = '-'
if threeD:
    _, end = last_state(case)
    grid = open(os.path.join(case, 'constant', 'grid')).read()
    dx = float(re.search(r'cellSize\s+([0-9.e+-]+)\s*;', grid).group(1))
    B = dx * int(re.search(r'nCells\s+\(\s*\d+\s+(\d+)', grid).group(1))
    sand_ = [(x[1], math.sqrt(sum(c * c for c in u))) for b, x, u in
             zip(end['body'], end['Points'], end['displacement']) if b == 0]
    moved = [y for y, u in sand_ if u > 0.1 * travel[-1]]
    reach = f'{max(moved):.3f}' if moved else '0'
    side = f'{100 * max(u for y, u in sand_ if y > B - dx) / travel[-1]:.3f}'
print(f'{h:.4f} {F1:.1f} {F3:.1f} {M1:.1f} {M3:.1f} {P1:.1f} {S1:.1f} {S3:.1f} {min(d1, travel[-1]) * 1e3:.1f} {reach} {side}')
if '-series' in sys.argv:
    with open(os.path.join(case, 'series.dat'), 'w') as f:
        f.write(f'# h = {h:.4f} m, w = {w if threeD else "plane"}; mean over {d0 * 1e3:g} ... {d1 * 1e3:g} mm: '
                f'F_x1 = {F1:.1f}, F_x3 = {F3:.1f} N/m; McKyes & Ali {M1:.1f}, Sokolovski {S1:.1f} N/m\n')
        f.write('# travel_mm Fx1 Fx3 [N/m]\n')
        for d, a, b in zip(travel, f1, f3):
            f.write(f'{d * 1e3:.4f} {a:.2f} {b:.2f}\n')
