#!/usr/bin/env python3
"""Footing pressure against settlement next to a vertical cut (seed 5.3.4, fig. 5.16).

P = Fy / b, Fy the soil's force on the footing [N/m] (postProcessing/forces/0/forces.dat),
b = 0.4 m, against the settlement -dy (zero until the load stage wakes the footing). The
failure pressure P_fail is the plateau of the curve: the mean of P over the settlements
FROM..TO mm (default 10..20 mm: the curve has flattened by 10 mm, and the seed's figure
ends at 18 mm). Its error is taken against the field collapse pressure of test A, 150 kPa
(the seed: PICCUS and PLAXIS about 105 kPa, -30 %, read off fig. 5.16).
Prints: P_fail [kPa], its error against 150 kPa [%], the peak of P [kPa], the mean of P
over the last 5 mm of the push [kPa], the settlement reached [mm]. With -series writes
settlement [mm] and P [kPa] to pressure.dat in the case.
Usage: analyse.py CASE [FROM TO] [-series]
"""
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from gpicdat import read_columns  # noqa: E402

B = 0.4            # footing width [m]
FIELD = 150.0      # field test A collapse pressure [kPa]


def main():
    args = [a for a in sys.argv[1:] if a != '-series']
    if not args:
        sys.exit(__doc__.strip().splitlines()[-1])
    case = args[0]
    lo, hi = (float(args[1]), float(args[2])) if len(args) >= 3 else (10.0, 20.0)
    path = os.path.join(case, 'postProcessing', 'forces', '0', 'forces.dat')
    cols = read_columns(path)
    rows = [(-dy * 1e3, fy / B / 1e3) for dy, fy in zip(cols['footing:dy'], cols['footing:Fy']) if dy < 0]
    if not rows:
        sys.exit(f'{path}: the footing never moved')
    settlement, pressure = zip(*rows)
    end = settlement[-1]
    window = [p for s, p in rows if lo <= s <= hi]
    if not window or end < hi:
        sys.exit(f'{path}: the push reached {end:.1f} mm, short of the window {lo:g}..{hi:g} mm')
    p_fail = sum(window) / len(window)
    last = [p for s, p in rows if s >= end - 5]
    print(f'{p_fail:.1f} {(p_fail - FIELD) / FIELD * 100:.2f} {max(pressure):.1f} '
          f'{sum(last) / len(last):.1f} {end:.1f}')
    if '-series' in sys.argv:
        with open(os.path.join(case, 'pressure.dat'), 'w') as f:
            f.write('# settlement [mm] footing pressure P [kPa]\n')
            f.write('0 0\n')
            for s, p in rows:
                f.write(f'{s:.4f} {p:.3f}\n')


if __name__ == '__main__':
    main()
