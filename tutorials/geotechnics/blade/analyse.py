#!/usr/bin/env python3
"""Mean blade forces (seed Case 4.7) against Sokolovski's method of characteristics.

The forces function object writes the force of the sand on the blade (blade:Fx, blade:Fy,
postProcessing/forces/*/forces.dat); the seed plots the force of the blade on the sand,
    F_x1 = -blade:Fx (the push),  F_x2 = -blade:Fy (< 0: the sand lifts the blade),
and averages it over t = 2 ... 7 s at 5 mm/s, i.e. over 10 ... 35 mm of blade travel. The
mean here is the trapezoidal time average over the samples with 10 <= blade:dx <= 35 mm, so
a faster blade is averaged over the same travel.

The depth h is measured on the case itself, from the particles that picInit made (time 0):
the top of the sand's particle domains less the foot of the blade's. Sokolovski's forces
(picSokolovski) are those of a rough vertical wall at that depth, with phi and rho of the
material `sand` and mu of constant/contactProperties. Error % = (ours - Sokolovski) /
Sokolovski x 100 (seed eq. 4.7.1).

The front face alone (the forces function object's face `front`), which is Sokolovski's
wall, is averaged the same way: the whole blade's forces also hold its foot, pressed up by
the sand beneath, and its back.

Usage: analyse.py <case> [-window d0 d1] [-nominal h] [-series]
Prints: h Fx1 Fx2 Fx1_Sokolovski Fx2_Sokolovski error1_% error2_% (Fx1 - Fx1_Sokolovski),
the end of the window reached [mm] (less than d1 when a run stopped early), then the front
face's Fx1 Fx2 error1_% error2_% ('-' without the face).
-series writes series.dat in the case: blade travel [mm], F_x1, F_x2 [N/m], and both forces
scaled to the nominal depth by (h_nominal / h)^2, the scaling of Sokolovski's solution.
"""
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
import gpicdat  # noqa: E402
from gpicdat import case_entries, tool_depth, tool_forces, window_mean  # noqa: E402


def option(name, count, default):
    return gpicdat.option(sys.argv, name, count, default)


def sokolovski(h, case):
    sand = case_entries(os.path.join(case, 'constant', 'materials'), 'sand')
    mu = case_entries(os.path.join(case, 'constant', 'contactProperties'), None)['mu']
    out = subprocess.run(['picSokolovski', '-phi', sand['phi'], '-mu', mu, '-rho', sand['rho'],
                          '-h', repr(h)], capture_output=True, text=True, check=True).stdout
    row = next(line.split() for line in out.splitlines() if re.match(r'\s*\d+\.\d+\s+\d', line))
    return float(row[2]), float(row[3])


def mean(t, f, keep):
    value = window_mean(t, f, keep)
    if value is None:
        sys.exit('analyse.py: no forces in the averaging window (is the run complete?)')
    return value


case = sys.argv[1]
d0, d1 = option('-window', 2, [0.010, 0.035])
t, fx1, fx2, travel = tool_forces(case, 'blade')
fx1, fx2 = [-f for f in fx1], [-f for f in fx2]  # the force of the blade on the material
h = tool_depth(case)
keep = [d0 - 1e-9 <= d <= d1 + 1e-9 for d in travel]
F1, F2 = mean(t, fx1, keep), mean(t, fx2, keep)
S1, S2 = sokolovski(h, case)
try:
    _, gx1, gx2, _ = tool_forces(case, 'blade', 'front')
    G1, G2 = mean(t, [-f for f in gx1], keep), mean(t, [-f for f in gx2], keep)
    front = f'{G1:.1f} {G2:.1f} {(G1 - S1) / S1 * 100:.2f} {(G2 - S2) / S2 * 100:.2f}'
except KeyError:  # a case without the face
    front = '- - - -'
print(f'{h:.4f} {F1:.1f} {F2:.1f} {S1:.1f} {S2:.1f} '
      f'{(F1 - S1) / S1 * 100:.2f} {(F2 - S2) / S2 * 100:.2f} {F1 - S1:.1f} {min(d1, travel[-1]) * 1e3:.1f} {front}')
if '-series' in sys.argv:
    scale = (option('-nominal', 1, [h])[0] / h) ** 2
    with open(os.path.join(case, 'series.dat'), 'w') as f:
        f.write(f'# h = {h:.4f} m; Sokolovski F_x1 = {S1:.1f}, F_x2 = {S2:.1f} N/m; '
                f'mean over {d0 * 1e3:g} ... {d1 * 1e3:g} mm: F_x1 = {F1:.1f}, F_x2 = {F2:.1f} N/m\n')
        f.write(f'# travel_mm Fx1 Fx2 Fx1_scaled Fx2_scaled (x (h_nominal/h)^2 = {scale:.4f})\n')
        for d, a, b in zip(travel, fx1, fx2):
            f.write(f'{d * 1e3:.4f} {a:.2f} {b:.2f} {a * scale:.2f} {b * scale:.2f}\n')
