#!/usr/bin/env python3
"""Footing pressure against settlement and the collapse pressure of a rough circular footing.

Reference (the Tresca soil): a rigid, perfectly rough circular footing on the surface of a
weightless Tresca soil (cohesion c, no friction) collapses at the mean pressure
    q_u = 6.05 c                  (Eason & Shield 1960, slip lines; exact),
6.05 x 26 kPa = 157.3 kPa here; a smooth one at 5.69 c (Shield 1955); a strip at
(2 + pi) c = 5.14 c (Prandtl 1920), rough or smooth.

With -silt (footingBearing's Heilbronn silt: c 26 kPa, phi 27 deg, gamma 20.5 kN/m^3) the
strip's factors of the seed's eqs. 5.3.1-5.3.2 (N_c = 23.94, N_q = N_d = 13.20,
N_b = 6.216) with De Beer's (1970) shape factors for a circle as tabulated by Vesic (1973),
s_c = 1 + N_q / N_c = 1.551 and s_gamma = 0.6, the width b the diameter 2 R:
    q_u = c N_c s_c + gamma 2R N_b s_gamma = 965.7 + 30.6 = 996.3 kPa,
an estimate, not a bound (README.md).

The run is axisymmetric: the `forces` function object's Faxial is the soil's axial force on
the whole footing [N] (2 pi times Fy per radian), so P = Faxial / (pi R^2), R = 0.2 m,
against the settlement -dy. q_u is the mean of P over the settlements FROM..TO mm (default
10..15 mm for the Tresca soil, 5-7.5 % of R, past the knee of the curve; 30..50 mm for the
silt, footingBearing's window); a push that stops short of TO uses what it has beyond FROM.
Prints: q_u [kPa], its error against the reference [%], q_u / c, the peak of P [kPa], the
settlement reached [mm]. With -series writes settlement [mm], P [kPa] and P / c to
pressure.dat in the case.
Usage: analyse.py CASE [FROM TO] [-silt] [-series]
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from gpicdat import read_columns, report_footing  # noqa: E402

C = 26e3            # cohesion [Pa] (constant/materials)
R = 0.2             # footing radius [m] (constant/bodies)


def silt_capacity():
    """c N_c s_c + gamma 2R N_b s_gamma [Pa] for the silt (phi 27 deg, gamma 20.5 kN/m^3)."""
    t, s = math.tan(math.radians(27.0)), math.sin(math.radians(27.0))
    n_q = math.exp(math.pi * t) * (1 + s) / (1 - s)
    n_c, n_b = (n_q - 1) / t, (n_q - 1) * t
    return C * n_c * (1 + n_q / n_c) + 20.5e3 * 2 * R * n_b * 0.6


def main():
    silt = '-silt' in sys.argv
    args = [a for a in sys.argv[1:] if a not in ('-series', '-silt')]
    if not args:
        sys.exit(__doc__.strip().splitlines()[-1])
    case = args[0]
    lo, hi = (float(args[1]), float(args[2])) if len(args) >= 3 else ((30.0, 50.0) if silt else (10.0, 15.0))
    reference = (silt_capacity() if silt else 6.05 * C) / 1e3   # kPa
    path = os.path.join(case, 'postProcessing', 'forces', '0', 'forces.dat')
    cols = read_columns(path)
    settlement = [-dy * 1e3 for dy in cols['footing:dy']]                       # mm
    pressure = [f / (math.pi * R * R) / 1e3 for f in cols['footing:Faxial']]   # kPa
    report_footing(case, path, settlement, pressure, reference, C, lo, hi, '-series' in sys.argv)


if __name__ == '__main__':
    main()
