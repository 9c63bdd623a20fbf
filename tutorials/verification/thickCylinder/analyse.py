#!/usr/bin/env python3
"""The thick-walled cylinder's stresses against Lame's closed form.

Usage: analyse.py RUN_DIR [CELL_SIZE] [-plane]
Prints: the largest error of the column means of sigma_rr, sigma_tt, sigma_zz over the wall
(the loaded column aside) and the error of the inner face's displacement, both in % of p;
writes RUN_DIR/stress.dat (r, the column means and Lame's values) for the plot.
-plane: the tube's cross-section in plane strain (a quarter ring in x-y): the means are over
rings a cell thick (by the initial radius) of the polar stresses sigma_rr, sigma_tt (in the
plane) and sigma_zz (out of it), the loaded inner ring and the outer ring, whose particles
stair-step the free surface, aside.
Lame (a long cylinder, eps_zz = 0): sigma_rr = A - B/r^2, sigma_tt = A + B/r^2,
sigma_zz = nu (sigma_rr + sigma_tt), A = p a^2/(b^2 - a^2), B = A b^2;
u(r) = (1 + nu)/E ((1 - 2 nu) A r + B / r)."""
import glob
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ['GPIC_DIR'], 'etc', 'python'))
from gpicdat import read_particles  # noqa: E402

A_IN, B_OUT, P, E, NU = 0.1, 0.2, 1e4, 1e7, 0.3
A = P * A_IN ** 2 / (B_OUT ** 2 - A_IN ** 2)
B = A * B_OUT ** 2


def lame(r):
    rr, tt = A - B / r ** 2, A + B / r ** 2
    return rr, tt, NU * (rr + tt)


def polar(x, x0, s):
    """(r, sigma_rr, sigma_tt, sigma_zz, radial displacement, initial r) of a particle of the
    plane-strain cross-section at x (initially x0)."""
    r, r0 = math.hypot(x[0], x[1]), math.hypot(x0[0], x0[1])
    c, n = x[0] / r, x[1] / r
    xx, xy, yy = s[0], s[1], s[4]
    return (r, c * c * xx + n * n * yy + 2 * c * n * xy, n * n * xx + c * c * yy - 2 * c * n * xy, s[8],
            ((x[0] - x0[0]) * x0[0] + (x[1] - x0[1]) * x0[1]) / r0, r0)


def main(run, h, plane):
    last = max(glob.glob(os.path.join(run, '[0-9]*', 'particles.vtp')),
               key=lambda f: float(os.path.basename(os.path.dirname(f))))
    p = read_particles(last)
    columns = {}
    for x, x0, s in zip(p['Points'], p['initialPosition'], p['stress']):
        row = polar(x, x0, s) if plane else (x[0], s[0], s[8], s[4], x[0] - x0[0], x0[0])
        k = int((row[5] - A_IN) / h + 1e-9) if plane else int(x0[0] / h + 1e-9)
        columns.setdefault(k, []).append(row)
    inner = min(columns)
    # The outer ring of the cross-section stands in steps along the free surface.
    skipped = (inner, max(columns)) if plane else (inner,)
    worst = 0.0
    with open(os.path.join(run, 'stress.dat'), 'w') as out:
        out.write('# r sigma_rr sigma_tt sigma_zz (column means) Lame_rr Lame_tt Lame_zz [Pa]\n')
        for k in sorted(columns):
            rows = columns[k]
            n = len(rows)
            r, rr, tt, zz = (sum(row[i] for row in rows) / n for i in range(4))
            exact = lame(r)
            out.write('%g %g %g %g %g %g %g\n' % ((r, rr, tt, zz) + exact))
            if k not in skipped:  # the loaded column carries p as particle forces
                worst = max(worst, *(abs(a - b) for a, b in zip((rr, tt, zz), exact)))
    # The particles next to the inner face: initially within a quarter cell (plane: a
    # quarter diagonal) of it.
    face = [row for row in columns[inner] if row[5] < A_IN + 0.25 * h * (math.sqrt(2) if plane else 1) + 1e-9]
    u = sum(row[4] for row in face) / len(face)
    exact_u = sum((1 + NU) / E * ((1 - 2 * NU) * A * row[5] + B / row[5]) for row in face) / len(face)
    print('%.3f %.3f' % (100 * worst / P, 100 * (u - exact_u) / exact_u))


if __name__ == '__main__':
    args = [a for a in sys.argv[1:] if a != '-plane']
    main(args[0], float(args[1]) if len(args) > 1 else 0.01, '-plane' in sys.argv)
