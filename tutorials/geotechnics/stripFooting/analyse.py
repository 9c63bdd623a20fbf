#!/usr/bin/env python3
"""Footing pressure against settlement and the collapse pressure of a strip footing.

Reference: a rigid strip footing of width B on the surface of a weightless Tresca soil
(cohesion c, no friction) collapses at the mean pressure
    q_u = (2 + pi) c = 5.1416 c,
5.1416 x 26 kPa = 133.68 kPa here, smooth or rough alike: Hill's mechanism for a smooth base
and Prandtl's for a rough one give the same upper bound, and a statically admissible stress
field the same lower bound (Prandtl 1920, Hill 1950; Chen 1975, "Limit analysis and soil
plasticity"; Davis & Selvadurai 2002, "Plasticity and Geomechanics").

The run is a plane-strain half model: the `forces` function object's Fy is the soil's
vertical force on half the footing [N/m], so P = Fy / (B/2), B/2 = 0.2 m, against the
settlement -dy. q_u is the mean of P over the settlements FROM..TO mm (default 10..15 mm,
5-7.5 % of B/2, past the knee of the curve); a push that stops short of TO uses what it
has beyond FROM.
Prints: q_u [kPa], its error against the reference [%], q_u / c, the peak of P [kPa], the
settlement reached [mm]. With -series writes settlement [mm], P [kPa] and P / c to
pressure.dat in the case.
Usage: analyse.py CASE [FROM TO] [-series]
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from gpicdat import read_columns, report_footing  # noqa: E402

C = 26e3            # cohesion [Pa] (constant/materials)
HALF_B = 0.2        # the footing's half-width [m] (constant/bodies)


def main():
    args = [a for a in sys.argv[1:] if a != '-series']
    if not args:
        sys.exit(__doc__.strip().splitlines()[-1])
    case = args[0]
    lo, hi = (float(args[1]), float(args[2])) if len(args) >= 3 else (10.0, 15.0)
    reference = (2 + math.pi) * C / 1e3   # kPa
    path = os.path.join(case, 'postProcessing', 'forces', '0', 'forces.dat')
    cols = read_columns(path)
    settlement = [-dy * 1e3 for dy in cols['footing:dy']]           # mm
    pressure = [f / HALF_B / 1e3 for f in cols['footing:Fy']]       # kPa
    report_footing(case, path, settlement, pressure, reference, C, lo, hi, '-series' in sys.argv)


if __name__ == '__main__':
    main()
