#!/usr/bin/env python3
"""Load against displacement of a strip anchor pulled out of sand (seed 5.2), its peak and
its k_4 ultimate capacity (Rowe & Davis 1982).

The pull P [N/m] is the force of the sand on the anchor against the pull direction, less its
value when the pull starts (the anchor then rests on the sand under it: the rod load is zero,
as in the experiments); the vertical half model doubles it. The displacement is the
anchor's travel. Both are smoothed by a running mean over SMOOTH = 0.1 mm of travel (the
undamped sand rings by a few per cent).

  vertical (5.2.1): load factor q = P/B [kPa] (the seed's "P/(LB)" of figs. 5.3-5.4).
  inclined (5.2.2): load factor N = P/(gamma B h) [-] (figs. 5.8-5.9).

k_4 (Rowe & Davis 1982a, seed fig. 5.8): the load at which the displacement is 4 times the
elastic one. With K_e the initial slope (least squares through the origin over the part of
the curve below a quarter of the peak), it is the load where the curve meets the line
P = K_e d / 4.

Closed forms for the vertical strip anchor (cover h, width B, friction angle phi), as
breakout factors P/(gamma B h):
  rigid-block upper bound (slip planes at phi to the vertical, associated flow; the
  plane-strain mechanism of Murray & Geddes 1987):      1 + (h/B) tan phi
  vertical slip surfaces with the uplift coefficient K_u (Meyerhof & Adams 1968; K_u about
  0.9 at phi = 32 deg):                                 1 + K_u (h/B) tan phi

The compared value: vertical, the ultimate load factor q_u, the mean of q over the last 40 %
of the pull (1.5-2.5 mm for h/B = 3, 3.6-6 mm for h/B = 5: the curve's plateau, less
sensitive to the ringing than the peak); inclined, N at 1.6 mm of travel (where the seed's
fig. 5.8 ends, at about 2.5 for h/B = 2).

Prints: the compared value, peak [kPa or -], displacement at the peak [mm], k_4 [kPa or -],
displacement at k_4 [mm] ('-' when the pull stopped before the curve met the k_4 line), the
travel reached [mm]. With -series writes load.dat (travel [mm], load factor) in the case.
Usage: analyse.py CASE vertical|inclined HB [-series]
       analyse.py -closedForm HB   (the two closed forms for the vertical case, kPa)
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from gpicdat import read_columns  # noqa: E402

B = 0.051                                  # anchor width [m] (both cases)
VERTICAL = {'gamma': 1519 * 9.81, 'phi': 32.0}    # table 5.1 (14.9 kN/m^3)
INCLINED = {'gamma': 1713 * 9.81}                 # table 5.3 (16.8 kN/m^3)
PULL45 = (math.sqrt(0.5), math.sqrt(0.5))         # unit pull direction of 5.2.2
SMOOTH = 0.1                               # running-mean window [mm]
K_U = 0.9                                  # Meyerhof & Adams' uplift coefficient, phi = 32 deg


def closed_forms(hb):
    """(upper bound, Meyerhof-Adams) load factors P/B [kPa] of the vertical case."""
    t = math.tan(math.radians(VERTICAL['phi']))
    gh = VERTICAL['gamma'] * hb * B / 1e3
    return (1 + hb * t) * gh, (1 + K_U * hb * t) * gh


def running_mean(d, q, width):
    """q averaged over the samples within width/2 of each d (d increasing)."""
    out, lo, hi, total = [], 0, 0, 0.0
    for k in range(len(d)):
        while hi < len(d) and d[hi] <= d[k] + 0.5 * width:
            total += q[hi]
            hi += 1
        while d[lo] < d[k] - 0.5 * width:
            total -= q[lo]
            lo += 1
        out.append(total / (hi - lo))
    return out


def k4(d, q, peak):
    """(k_4 load, its displacement) or (None, None) when the curve never meets P = K_e d / 4."""
    early = [(x, y) for x, y in zip(d, q) if 0 < x and y <= 0.25 * peak]
    if len(early) < 3:
        return None, None
    ke = sum(x * y for x, y in early) / sum(x * x for x, _ in early)
    for k in range(1, len(d)):
        g0, g1 = q[k - 1] - ke * d[k - 1] / 4, q[k] - ke * d[k] / 4
        if g0 > 0 >= g1 and q[k] > 0.25 * peak:
            s = g0 / (g0 - g1)
            return q[k - 1] + s * (q[k] - q[k - 1]), d[k - 1] + s * (d[k] - d[k - 1])
    return None, None


def main():
    if sys.argv[1:2] == ['-closedForm']:
        print('%.3f %.3f' % closed_forms(float(sys.argv[2])))
        return
    args = [a for a in sys.argv[1:] if a != '-series']
    if len(args) != 3 or args[1] not in ('vertical', 'inclined'):
        sys.exit(__doc__.strip().splitlines()[-2])
    case, kind, hb = args[0], args[1], float(args[2])
    path = os.path.join(case, 'postProcessing', 'forces', '0', 'forces.dat')
    c = read_columns(path)
    dx, dy, fx, fy = c['anchor:dx'], c['anchor:dy'], c['anchor:Fx'], c['anchor:Fy']
    if kind == 'vertical':
        pull = [-2 * f for f in fy]                       # both halves [N/m]
        scale = 1 / (B * 1e3)                             # P/B [kPa]
    else:
        pull = [-(x * PULL45[0] + y * PULL45[1]) for x, y in zip(fx, fy)]
        scale = 1 / (INCLINED['gamma'] * B * hb * B)      # P/(gamma B h)
    start = max(k for k in range(len(dy)) if dx[k] == 0 and dy[k] == 0)   # the pull starts
    d = [math.hypot(x, y) * 1e3 for x, y in zip(dx[start:], dy[start:])]  # mm
    q = [(p - pull[start]) * scale for p in pull[start:]]
    if len(d) < 10:
        sys.exit(f'{path}: {len(d)} samples of the pull, too few')
    qs = running_mean(d, q, SMOOTH)
    kpeak = max(range(len(qs)), key=qs.__getitem__)
    load, at = k4(d, qs, qs[kpeak])
    fmt = '%.3f' if kind == 'vertical' else '%.4f'
    if kind == 'vertical':
        window = [y for x, y in zip(d, q) if x >= 0.6 * d[-1]]
        compared = fmt % (sum(window) / len(window))
    else:
        k = next((k for k in range(1, len(d)) if d[k] >= 1.6), None)
        compared = '-' if k is None else fmt % (qs[k - 1] + (1.6 - d[k - 1]) / (d[k] - d[k - 1]) * (qs[k] - qs[k - 1]))
    print(compared, fmt % qs[kpeak], '%.3f' % d[kpeak], fmt % load if load else '-', '%.3f' % at if at else '-',
          '%.3f' % d[-1])
    if '-series' in sys.argv:
        with open(os.path.join(case, 'load.dat'), 'w') as f:
            f.write('# travel [mm] load factor (%s), smoothed over %g mm\n'
                    % ('P/B [kPa]' if kind == 'vertical' else 'P/(gamma B h) [-]', SMOOTH))
            for x, y in zip(d, qs):
                f.write(f'{x:.5f} {y:.5f}\n')


if __name__ == '__main__':
    main()
