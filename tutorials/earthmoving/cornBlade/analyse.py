#!/usr/bin/env python3
"""Mean draft force of the blade in corn (seed Case 6.2.5) against Sokolovski and the experiment.

The forces function object writes the force of the corn on the blade (blade:Fx, blade:Fy,
postProcessing/forces/*/forces.dat); the seed plots the force of the blade on the corn,
    F_x1 = -blade:Fx (the draft force),  F_x2 = -blade:Fy (< 0: the corn lifts the blade),
and averages the draft force over 15 ... 35 mm of blade displacement (fig. 6.13). The mean
here is the trapezoidal time average over the samples with 15 <= blade:dx <= 35 mm; the
fill stage (blade:dx = 0) is outside the window.

The depth h is measured on the case: the top of the corn's particle domains at time 0 less
the blade's foot. Sokolovski's forces (picSokolovski) are those of a rough vertical wall at
that depth, with phi and rho of the material `corn` and mu of constant/contactProperties
(delta = atan 0.249 = 14 deg).

The experiment (fig. 6.14) is only graphical; its draft forces are derived from the seed's
stated percentages: nonpolar = Sokolovski x (1.12, 1.06, 1.05) and = experiment x (0.75,
0.89, 0.91) at h = 150, 250, 350 mm, so experiment = Sokolovski x 1.12/0.75, 1.06/0.89,
1.05/0.91. At other depths there is no experiment value ('-').

Errors [%]: (ours - reference) / reference x 100, reference Sokolovski or the experiment.

Usage: analyse.py <case> [-window d0 d1] [-series] [-pdr d0 d1] [-surface]
Prints: h Fx1 Fx2 Fx1_Sokolovski Fx2_Sokolovski errorSok1_% errorSok2_% Fx1_experiment
errorExp1_%   (forces in N/m of blade width; the rig is 0.2 m wide: x 0.2 for N)
-series writes series.dat in the case: blade travel [mm], F_x1, F_x2 [N/m].
-pdr d0 d1 writes pdr.dat: the particle displacement ratio PDR = |particle displacement| /
|blade displacement| over the increment between the written times nearest to the blade
travels d0 and d1 [m] (the seed: 5 ... 15 mm), and prints the blade travels used and how far
in front of the blade the zone PDR >= 0.15 reaches the surface (Sokolovski: x_s).
-surface writes surface.dat: the free surface at blade travels of 100, 200, 300, 400 mm.
"""
import glob
import math
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
import gpicdat  # noqa: E402
from gpicdat import case_entries, read_particles, tool_depth, tool_forces, window_mean  # noqa: E402

# Seed 6.2.5, fig. 6.14 and its text: nonpolar / Sokolovski and nonpolar / experiment.
SEED_NONPOLAR_SOK = {0.15: 1.12, 0.25: 1.06, 0.35: 1.05}
SEED_NONPOLAR_EXP = {0.15: 0.75, 0.25: 0.89, 0.35: 0.91}


def option(name, count, default):
    return gpicdat.option(sys.argv, name, count, default)


def sokolovski(h, case):
    """(F_x1, F_x2, x_s) of a rough wall of depth h in the case's corn."""
    corn = case_entries(os.path.join(case, 'constant', 'materials'), 'corn')
    mu = case_entries(os.path.join(case, 'constant', 'contactProperties'), None)['mu']
    out = subprocess.run(['picSokolovski', '-phi', corn['phi'], '-mu', mu, '-rho', corn['rho'],
                          '-h', repr(h)], capture_output=True, text=True, check=True).stdout
    row = next(line.split() for line in out.splitlines() if re.match(r'\s*\d+\.\d+\s+\d', line))
    return float(row[2]), float(row[3]), float(row[6])


def mean(t, f, keep):
    value = window_mean(t, f, keep)
    if value is None:
        sys.exit('analyse.py: no forces in the averaging window (is the run complete?)')
    return value


def experiment(h):
    """The experiment's draft force per metre, derived from Sokolovski at the nominal depth."""
    for hn, ratio in SEED_NONPOLAR_SOK.items():
        if abs(h - hn) < 1e-3:
            return sokolovski(hn, case)[0] * ratio / SEED_NONPOLAR_EXP[hn]
    return None


def states(case):
    """(blade travel [m], directory, particles) of every written time, in time order."""
    times = []
    for d in glob.glob(os.path.join(case, '[0-9]*')):
        name = os.path.basename(d)
        if re.fullmatch(r'[0-9.e+-]+', name) and os.path.isfile(os.path.join(d, 'particles.vtp')):
            times.append((float(name), d))
    times.sort()
    out = []
    for t, d in times:
        part = read_particles(os.path.join(d, 'particles.vtp'))
        blade = [u[0] for b, u in zip(part['body'], part['displacement']) if b == 1]
        out.append((sum(blade) / len(blade), d, part))
    return out


def surface(case, travels, width=0.01):
    """The corn's free surface (top of the particle domains in bins of `width`) at the written
    times nearest to the blade travels [m] (seed figs. 6.9, 6.11: 100 ... 400 mm, h = 0.2 m)."""
    written = states(case)
    with open(os.path.join(case, 'surface.dat'), 'w') as f:
        f.write('# free surface of the corn: x1 [m], x2 [m]; one block per blade travel\n')
        for want in travels:
            travel, d, part = min(written, key=lambda s: abs(s[0] - want))
            top = {}
            for b, x, hs in zip(part['body'], part['Points'], part['halfSize']):
                if b == 0:
                    k = int(x[0] // width)
                    top[k] = max(top.get(k, -1.0), x[1] + hs[1])
            f.write(f'# travel {travel * 1e3:.1f} mm ({os.path.basename(d)} s)\n')
            for k in sorted(top):
                f.write(f'{(k + 0.5) * width:.4f} {top[k]:.4f}\n')
            f.write('\n\n')
            print(f'surface: blade travel {travel * 1e3:.1f} mm, highest {max(top.values()):.3f} m')


def pdr(case, d0, d1, x_s):
    """PDR over the increment between the written times nearest to blade travels d0, d1."""
    written = states(case)
    a = min(written, key=lambda s: abs(s[0] - d0))
    b = min(written, key=lambda s: abs(s[0] - d1))
    if b[0] - a[0] <= 0:
        sys.exit('analyse.py: no blade travel between the written times for -pdr')
    before = {i: x for i, x in zip(a[2]['id'], a[2]['Points'])}
    part = b[2]
    front = max(x[0] + s[0] for bb, x, s in zip(part['body'], part['Points'], part['halfSize']) if bb == 1)
    rows = []
    for i, bb, x in zip(part['id'], part['body'], part['Points']):
        if bb != 0 or i not in before:
            continue
        x0 = before[i]
        rows.append((x[0], x[1], math.hypot(x[0] - x0[0], x[1] - x0[1]) / (b[0] - a[0])))
    with open(os.path.join(case, 'pdr.dat'), 'w') as f:
        f.write(f'# PDR = |particle displacement| / blade displacement over blade travel '
                f'{a[0] * 1e3:.1f} ... {b[0] * 1e3:.1f} mm; blade front at x1 = {front:.4f} m\n')
        f.write('# x1 x2 PDR\n')
        for r in rows:
            f.write(f'{r[0]:.5f} {r[1]:.5f} {r[2]:.4f}\n')
    # The band rises from the blade's foot to the surface: its reach there is the farthest
    # particle with PDR >= 0.15.
    moving = [r for r in rows if r[2] >= 0.15]
    reach = max(r[0] for r in moving) - front if moving else 0.0
    print(f'PDR: blade travel {a[0] * 1e3:.1f} ... {b[0] * 1e3:.1f} mm; PDR >= 0.15 reaches '
          f'{reach:.3f} m in front of the blade (Sokolovski x_s = {x_s:.3f} m)')


case = sys.argv[1]
d0, d1 = option('-window', 2, [0.015, 0.035])
t, fx1, fx2, travel = tool_forces(case, 'blade')
fx1, fx2 = [-f for f in fx1], [-f for f in fx2]  # the force of the blade on the material
h = tool_depth(case)
keep = [d0 - 1e-9 <= d <= d1 + 1e-9 for d in travel]
F1, F2 = mean(t, fx1, keep), mean(t, fx2, keep)
S1, S2, xs = sokolovski(h, case)
E1 = experiment(h)
exp_cols = f'{E1:.1f} {(F1 - E1) / E1 * 100:.2f}' if E1 else '- -'
print(f'{h:.4f} {F1:.1f} {F2:.1f} {S1:.1f} {S2:.1f} '
      f'{(F1 - S1) / S1 * 100:.2f} {(F2 - S2) / S2 * 100:.2f} {exp_cols}')
if '-series' in sys.argv:
    with open(os.path.join(case, 'series.dat'), 'w') as f:
        f.write(f'# h = {h:.4f} m; Sokolovski F_x1 = {S1:.1f}, F_x2 = {S2:.1f} N/m; '
                f'mean over {d0 * 1e3:g} ... {d1 * 1e3:g} mm: F_x1 = {F1:.1f}, F_x2 = {F2:.1f} N/m\n')
        f.write('# travel_mm Fx1 Fx2 [N/m]\n')
        for d, a, b in zip(travel, fx1, fx2):
            if d > 0:
                f.write(f'{d * 1e3:.4f} {a:.2f} {b:.2f}\n')
if '-surface' in sys.argv:
    surface(case, [0.1, 0.2, 0.3, 0.4])
if '-pdr' in sys.argv:
    p0, p1 = option('-pdr', 2, [0.005, 0.015])
    pdr(case, p0, p1, xs)
