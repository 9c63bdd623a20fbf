#!/usr/bin/env python3
"""The wall's thrust in one run against its closed form.

    analyse.py <run> active|passive smooth|rough [-phi 30 -delta 20 -rho 1500 -H 1] [-series]

Prints P_h P_v P_h_ref P_v_ref error_h_% error_v_% reference: the mean horizontal and
vertical force of the backfill on the wall [N/m] over the travel window (active 1.5 ... 4.5
mm, passive 15 ... 45 mm), and the reference:
  smooth, active or passive: Rankine, K = (1 -+ sin phi) / (1 +- sin phi), P = K gamma H^2 / 2;
  rough, active: Coulomb's wedge with wall friction delta (vertical wall, level backfill),
      K_a = cos^2 phi / (cos delta (1 + sqrt(sin(phi + delta) sin phi / cos delta))^2),
      P_h = K_a gamma H^2 cos(delta) / 2, P_v = P_h tan delta;
  rough, passive: Sokolovski's characteristics (picSokolovski), since Coulomb's plane wedge
      overestimates the passive thrust once delta > phi / 3.
With -series it also writes <run>/series.dat: travel [mm], P_h and P_v [N/m] at every sample.
"""
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.environ['GPIC_DIR'], 'etc', 'python'))
from gpicdat import option, tool_forces, window_mean  # noqa: E402

run, mode, wall = sys.argv[1:4]
phi = math.radians(option(sys.argv, '-phi', 1, [30])[0])
delta = math.radians(option(sys.argv, '-delta', 1, [20])[0]) if wall == 'rough' else 0.0
rho = option(sys.argv, '-rho', 1, [1500])[0]
H = option(sys.argv, '-H', 1, [1.0])[0]
gamma = rho * 9.81
window = (1.5, 4.5) if mode == 'active' else (15.0, 45.0)

t, Fx, Fy, dx = tool_forces(run, 'wall')
if not t:
    sys.exit(f'{run}: no forces.dat')
travel = [abs(d) * 1e3 for d in dx]
if travel[-1] < window[1] - 1e-6:
    sys.exit(f'{run}: the wall travelled {travel[-1]:.1f} mm, short of the window {window[0]:g}..{window[1]:g} mm')
keep = [window[0] <= s <= window[1] for s in travel]
Ph = -window_mean(t, Fx, keep)
Pv = abs(window_mean(t, Fy, keep))

if wall == 'smooth':
    s = math.sin(phi)
    K = (1 - s) / (1 + s) if mode == 'active' else (1 + s) / (1 - s)
    Ph_ref, Pv_ref, reference = 0.5 * K * gamma * H * H, 0.0, 'Rankine'
elif mode == 'active':
    root = math.sqrt(math.sin(phi + delta) * math.sin(phi) / math.cos(delta))
    K = math.cos(phi) ** 2 / (math.cos(delta) * (1 + root) ** 2)
    Ph_ref = 0.5 * K * gamma * H * H * math.cos(delta)
    Pv_ref, reference = Ph_ref * math.tan(delta), 'Coulomb'
else:
    out = subprocess.run(['picSokolovski', '-phi', str(math.degrees(phi)), '-delta', str(math.degrees(delta)),
                          '-rho', str(rho), '-h', str(H)], capture_output=True, text=True, check=True).stdout
    row = [line.split() for line in out.splitlines() if line.strip().startswith('%.4f' % H)][-1]
    Ph_ref, Pv_ref, reference = float(row[2]), abs(float(row[3])), 'Sokolovski'

error = lambda ours, ref: '%.1f' % (100 * (ours - ref) / ref) if ref > 0 else '-'
if '-series' in sys.argv:  # travel [mm], P_h, P_v [N/m] for the plots
    with open(os.path.join(run, 'series.dat'), 'w') as f:
        f.write('# travel_mm P_h P_v\n')
        for s, fx, fy in zip(travel, Fx, Fy):
            f.write('%.4f %.1f %.1f\n' % (s, -fx, abs(fy)))
print('%.0f %.0f %.0f %.0f %s %s %s' % (Ph, Pv, Ph_ref, Pv_ref, error(Ph, Ph_ref), error(Pv, Pv_ref), reference))
