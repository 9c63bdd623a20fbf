#!/usr/bin/env python3
"""The thick-walled cylinder's stresses against Lame's closed form.

Usage: analyse.py RUN_DIR [CELL_SIZE]
Prints: the largest error of the column means of sigma_rr, sigma_tt, sigma_zz over the wall
(the loaded column aside) and the error of the inner face's displacement, both in % of p;
writes RUN_DIR/stress.dat (r, the column means and Lame's values) for the plot.
Lame (a long cylinder, eps_zz = 0): sigma_rr = A - B/r^2, sigma_tt = A + B/r^2,
sigma_zz = nu (sigma_rr + sigma_tt), A = p a^2/(b^2 - a^2), B = A b^2;
u(r) = (1 + nu)/E ((1 - 2 nu) A r + B / r)."""
import glob
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


def main(run, h):
    last = max(glob.glob(os.path.join(run, '[0-9]*', 'particles.vtp')),
               key=lambda f: float(os.path.basename(os.path.dirname(f))))
    p = read_particles(last)
    columns = {}
    for x, x0, s in zip(p['Points'], p['initialPosition'], p['stress']):
        k = int(x0[0] / h + 1e-9)
        columns.setdefault(k, []).append((x[0], s[0], s[8], s[4], x[0] - x0[0], x0[0]))
    inner = min(columns)
    worst = 0.0
    with open(os.path.join(run, 'stress.dat'), 'w') as out:
        out.write('# r sigma_rr sigma_tt sigma_zz (column means) Lame_rr Lame_tt Lame_zz [Pa]\n')
        for k in sorted(columns):
            rows = columns[k]
            n = len(rows)
            r, rr, tt, zz = (sum(row[i] for row in rows) / n for i in range(4))
            exact = lame(r)
            out.write('%g %g %g %g %g %g %g\n' % ((r, rr, tt, zz) + exact))
            if k != inner:  # the loaded column carries p as particle forces
                worst = max(worst, *(abs(a - b) for a, b in zip((rr, tt, zz), exact)))
    first = columns[inner]
    u = sum(row[4] for row in first if row[5] < A_IN + 0.25 * h + 1e-9) / \
        sum(1 for row in first if row[5] < A_IN + 0.25 * h + 1e-9)
    r0 = A_IN + 0.25 * h
    exact_u = (1 + NU) / E * ((1 - 2 * NU) * A * r0 + B / r0)
    print('%.3f %.3f' % (100 * worst / P, 100 * (u - exact_u) / exact_u))


if __name__ == '__main__':
    main(sys.argv[1], float(sys.argv[2]) if len(sys.argv) > 2 else 0.01)
