#!/usr/bin/env python3
"""Draft force per part, the corn carried and the tooth's wear of the 3D dragline bucket.

The forces function object writes the force of the corn on the half bucket (bucket:Fx) and
on each part of its STL (bucket.<part>:Fx); the draft force is that of the bucket on the
corn, for the whole bucket (the mirrored half added):
    F_x1 = -2 bucket:Fx [N],
against the bucket's x1 travel (bucket:dx), as the plane bucket (tutorials/earthmoving/bucket)
reports it per metre (x 0.2 m for the rig). F at a travel d is the trapezoidal time average
over |travel - d| <= 10 mm. The fill (toolFill, fill.dat) is the corn inside the bucket's
inside.stl as the bucket moves, x 2 [kg]; the wear (toolWear, wear.dat) the deepest Archard
wear of each part [m].

Usage: analyse.py <case> -series FILE   writes FILE (travel [mm], F_x1 [N], F_x1 per part [N],
                                        fill [kg]) and prints
                                        F(50) F(100) F(end) F_mean fill_end tooth_wear_m
                                        (F_mean over 50 mm ... the end; '-' where not reached)
       analyse.py <case> -parts         prints each part's share of the mean draft force, its
                                        deepest wear and the corn carried every 50 mm
"""
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from gpicdat import read_series, window_mean  # noqa: E402

WINDOW = 0.01
HALVES = 2   # the half model and its mirror


def at(t, f, travel, d):
    if not travel or max(travel) < d - 0.001:
        return None
    return window_mean(t, f, [abs(x - d) <= WINDOW + 1e-9 for x in travel])


def fmt(v, digits=1):
    return '-' if v is None else f'{v:.{digits}f}'


def parts_of(forces):
    return [name[len('bucket.'):-len(':Fx')] for name in forces if name.startswith('bucket.') and name.endswith(':Fx')]


def interpolate(t, f, time):
    """f at `time` by linear interpolation in t (clamped at the ends)."""
    if time <= t[0]:
        return f[0]
    for k in range(1, len(t)):
        if t[k] >= time:
            w = (time - t[k - 1]) / (t[k] - t[k - 1]) if t[k] > t[k - 1] else 1.0
            return f[k - 1] + w * (f[k] - f[k - 1])
    return f[-1]


def main():
    case = sys.argv[1]
    c = read_series(case, 'forces', 'forces.dat')
    if not c:
        sys.exit(f'{case}: no postProcessing/forces/*/forces.dat')
    t, travel = c['time'], c['bucket:dx']
    fx1 = [-HALVES * f for f in c['bucket:Fx']]
    parts = parts_of(c)
    part_fx1 = {p: [-HALVES * f for f in c[f'bucket.{p}:Fx']] for p in parts}
    fill = read_series(case, 'fill', 'fill.dat')
    wear = read_series(case, 'wear', 'wear.dat')
    keep = [x >= 0.05 for x in travel]
    end = max(travel)
    if '-series' in sys.argv:
        path = sys.argv[sys.argv.index('-series') + 1]
        with open(path, 'w') as f:
            f.write('# the force of the whole bucket on the corn, on each part; the corn in the bucket\n')
            f.write('# travel_mm Fx1_N ' + ' '.join(f'{p}_N' for p in parts) + ' fill_kg\n')
            for k, d in enumerate(travel):
                if d > 0:
                    carried = HALVES * interpolate(fill['time'], fill['mass'], t[k]) if fill else float('nan')
                    f.write(f'{d * 1e3:.4f} {fx1[k]:.3f} ' + ' '.join(f'{part_fx1[p][k]:.3f}' for p in parts)
                            + f' {carried:.4f}\n')
        mean = window_mean(t, fx1, keep) if end > 0.06 else None
        carried = HALVES * fill['mass'][-1] if fill else None
        tooth = wear.get('tooth:maxDepth', [None])[-1] if wear else None
        print(f'{fmt(at(t, fx1, travel, 0.05))} {fmt(at(t, fx1, travel, 0.1))} '
              f'{fmt(at(t, fx1, travel, end - WINDOW))} {fmt(mean)} {fmt(carried, 2)} '
              f'{"-" if tooth is None else f"{tooth:.3e}"}')
    if '-parts' in sys.argv:
        total = window_mean(t, fx1, keep) if end > 0.06 else None
        shares = []
        for p in parts:
            mean = window_mean(t, part_fx1[p], keep) if end > 0.06 else None
            share = '' if not total or mean is None else f' ({mean / total * 100:.0f} %)'
            shares.append(f'{p} {fmt(mean)}{share}')
        print('mean draft force per part [N]: ' + ', '.join(shares))
        if wear:
            depth = {p: wear[f'{p}:maxDepth'][-1] for p in parts if f'{p}:maxDepth' in wear}
            deepest = max(depth, key=depth.get)
            print(f'deepest wear: {deepest}; per part [m]: '
                  + ', '.join(f'{p} {v:.3g}' for p, v in depth.items())
                  + f'; worn volume {wear["volume"][-1] * HALVES:.3g} m^3')
        if fill:
            marks = [mm for mm in range(10, 1000, 10) if mm * 1e-3 <= end + 1e-6]
            carried = [HALVES * interpolate(fill['time'], fill['mass'],
                                            interpolate(travel, t, mm * 1e-3)) for mm in marks[4::5]]
            print('corn in the bucket [kg] every 50 mm: ' + ', '.join(f'{m:.2f}' for m in carried))


if __name__ == '__main__':
    main()
