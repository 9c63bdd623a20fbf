#!/usr/bin/env python3
"""Footing pressure against settlement and the bearing capacity (seed 5.3.3, eqs. 5.3.1-5.3.2).

Terzaghi's bearing capacity of a strip footing of width b on the surface of a soil with
cohesion c, friction angle phi and unit weight gamma, in the seed's form:
    P_max = c N_c + gamma b N_b,
    N_d = exp(pi tan phi) (1 + sin phi) / (1 - sin phi),
    N_c = (N_d - 1) / tan phi,   N_b = (N_d - 1) tan phi.
Heilbronn silt (table 5.5): c = 26 kPa, phi = 27 deg, gamma = 20.5 kN/m^3, b = 0.4 m:
N_d = 13.20, N_c = 23.94, N_b = 6.216, P_max = 674 kPa.

The half model's footing is 0.2 m wide: P = Fy / 0.2 m, Fy the soil's force on it [N/m]
(postProcessing/forces/0/forces.dat), against the settlement -dy. The curve keeps rising
slowly after the soil has failed (see README.md), so P_max is defined as the mean of P over
the settlements FROM..TO mm (default 30..50 mm, around the usual failure criterion of a
settlement of 10 % of the width); a push that stops short of TO uses what it has beyond
FROM. Prints: P_max [kPa], its error against 674 kPa [%], the peak of P [kPa], the mean
of P over the last 10 mm of the push [kPa], the settlement reached [mm]. With -series writes
settlement [mm] and P [kPa] to pressure.dat in the case.
Usage: analyse.py CASE [FROM TO] [-series]
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from gpicdat import read_columns, settled_window_mean  # noqa: E402

C, PHI, GAMMA, B = 26e3, 27.0, 20.5e3, 0.4   # table 5.5 and the footing width [Pa, deg, N/m^3, m]
HALF_WIDTH = 0.5 * B                          # the footing of the half model [m]


def bearing_capacity():
    """P_max [Pa] of eqs. 5.3.1-5.3.2."""
    t, s = math.tan(math.radians(PHI)), math.sin(math.radians(PHI))
    n_d = math.exp(math.pi * t) * (1 + s) / (1 - s)
    return C * (n_d - 1) / t + GAMMA * B * (n_d - 1) * t


def main():
    args = [a for a in sys.argv[1:] if a != '-series']
    if not args:
        sys.exit(__doc__.strip().splitlines()[-1])
    case = args[0]
    lo, hi = (float(args[1]), float(args[2])) if len(args) >= 3 else (30.0, 50.0)
    path = os.path.join(case, 'postProcessing', 'forces', '0', 'forces.dat')
    cols = read_columns(path)
    settlement = [-dy * 1e3 for dy in cols['footing:dy']]   # mm
    pressure = [fy / HALF_WIDTH / 1e3 for fy in cols['footing:Fy']]   # kPa
    end = settlement[-1]
    p_max = settled_window_mean(path, settlement, pressure, lo, hi)
    last = [p for s, p in zip(settlement, pressure) if s >= end - 10]
    reference = bearing_capacity() / 1e3
    print(f'{p_max:.1f} {(p_max - reference) / reference * 100:.2f} {max(pressure):.1f} '
          f'{sum(last) / len(last):.1f} {end:.1f}')
    if '-series' in sys.argv:
        with open(os.path.join(case, 'pressure.dat'), 'w') as f:
            f.write('# settlement [mm] footing pressure P [kPa]\n')
            for s, p in zip(settlement, pressure):
                f.write(f'{s:.4f} {p:.3f}\n')


if __name__ == '__main__':
    main()
