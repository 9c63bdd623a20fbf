#!/usr/bin/env python3
"""The thick-walled sphere's stresses against Lame's closed form.

Usage: analyse.py RUN_DIR [CELL_SIZE]
Prints: the largest error of the shell means of sigma_rhorho, sigma_thetatheta (meridional)
and sigma_phiphi (hoop) over the wall (the loaded inner shell and the outer shell, whose
particles stair-step the free surface, aside) and the error of the inner
face's radial displacement, in % of p and of u; writes RUN_DIR/stress.dat (rho, the shell
means and Lame's values) for the plot. Shells are a cell thick, by the particles' initial
distance rho from the centre; Lame's values are averaged over the same particles.
Lame (e.g. Timoshenko & Goodier, Theory of Elasticity, 3rd ed., sec. 137):
sigma_rhorho = -p (b^3/rho^3 - 1) / (b^3/a^3 - 1),
sigma_thetatheta = sigma_phiphi = p (b^3/(2 rho^3) + 1) / (b^3/a^3 - 1),
u(rho) = p a^3 / (E (b^3 - a^3)) ((1 - 2 nu) rho + (1 + nu) b^3 / (2 rho^2))."""
import glob
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ['GPIC_DIR'], 'etc', 'python'))
from gpicdat import read_particles  # noqa: E402

A_IN, B_OUT, P, E, NU = 0.1, 0.2, 1e4, 1e7, 0.3
K = P / (B_OUT ** 3 / A_IN ** 3 - 1)


def lame(rho):
    radial = -K * (B_OUT ** 3 / rho ** 3 - 1)
    hoop = K * (B_OUT ** 3 / (2 * rho ** 3) + 1)
    return radial, hoop, hoop


def lame_u(rho):
    return P * A_IN ** 3 / (E * (B_OUT ** 3 - A_IN ** 3)) * ((1 - 2 * NU) * rho + (1 + NU) * B_OUT ** 3 / (2 * rho ** 2))


def spherical(x, s):
    """sigma_rhorho, sigma_thetatheta, sigma_phiphi at x = (r, z) from the r-z stresses."""
    rho = math.hypot(x[0], x[1])
    c, n = x[0] / rho, x[1] / rho
    rr, rz, zz, tt = s[0], s[1], s[4], s[8]
    return (c * c * rr + n * n * zz + 2 * c * n * rz,
            n * n * rr + c * c * zz - 2 * c * n * rz,
            tt)


def main(run, h):
    last = max(glob.glob(os.path.join(run, '[0-9]*', 'particles.vtp')),
               key=lambda f: float(os.path.basename(os.path.dirname(f))))
    p = read_particles(last)
    shells = {}
    for x, x0, s in zip(p['Points'], p['initialPosition'], p['stress']):
        rho0 = math.hypot(x0[0], x0[1])
        k = int((rho0 - A_IN) / h)
        rho = math.hypot(x[0], x[1])
        u = ((x[0] - x0[0]) * x0[0] + (x[1] - x0[1]) * x0[1]) / rho0
        shells.setdefault(k, []).append((rho0,) + spherical(x, s) + lame(rho) + (u, lame_u(rho0)))
    inner, outer = min(shells), max(shells)
    worst = 0.0
    with open(os.path.join(run, 'stress.dat'), 'w') as out:
        out.write('# rho sigma_rhorho sigma_thetatheta sigma_phiphi (shell means) '
                  'Lame_rhorho Lame_thetatheta Lame_phiphi [Pa]\n')
        for k in sorted(shells):
            rows = shells[k]
            mean = [sum(row[i] for row in rows) / len(rows) for i in range(7)]
            out.write(' '.join('%g' % v for v in mean) + '\n')
            # The inner shell carries p as particle forces; the outer shell's particles
            # stand in steps along the free surface (README.md).
            if k not in (inner, outer):
                worst = max(worst, *(abs(mean[i] - mean[i + 3]) for i in (1, 2, 3)))
    # The particles next to the inner face: initially within a quarter cell of it.
    face = [row for row in shells[inner] if row[0] < A_IN + 0.25 * h * math.sqrt(2)]
    u = sum(row[7] for row in face) / len(face)
    exact_u = sum(row[8] for row in face) / len(face)
    print('%.3f %.3f' % (100 * worst / P, 100 * (u - exact_u) / exact_u))


if __name__ == '__main__':
    main(sys.argv[1], float(sys.argv[2]) if len(sys.argv) > 2 else 0.01)
