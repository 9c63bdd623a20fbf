#!/usr/bin/env python3
"""The rigid smooth circular punch against Boussinesq's settlement and Sadowsky's pressure.

Usage: analyse.py RUN_DIR | -extrapolate ERRORS_DAT
A rigid flat punch of radius a pressed with the total force P (the whole revolution) onto
an elastic half-space (E, nu) settles by (Boussinesq; Johnson 1985, "Contact Mechanics",
sec. 3.8; Timoshenko & Goodier, sec. 138)
    s = P (1 - nu^2) / (2 a E)
and presses on it with (Sadowsky; Johnson sec. 3.8)
    p(r) = P / (2 pi a sqrt(a^2 - r^2)),   mean p_m = P / (pi a^2).
P is the punch's axial force at the end of the run (postProcessing/forces: punch:Faxial,
2 pi times the per-radian force), s the punch's mean displacement. The pressure is the mean
-sigma_zz of the soil's particles in the top row of cells, binned by the cell columns, and
Sadowsky's p averaged over the same particles' radii. The particles lie h/4 and 3h/4 below
the surface; sigma_zz departs from the surface pressure only at second order in the depth
(a surface free of shear has d sigma_zz / dz = 0), so the surface value is the reference.
Prints: the settlement error (s / s_Boussinesq - 1) [%] and the largest
|p_numerical - p_Sadowsky| / p_m [%] over the columns whose centre lies within R_MAX a of
the axis (away from the edge, where p is unbounded), then P [N] and s [m]. Writes
RUN_DIR/pressure.dat (r, numerical and Sadowsky pressure over p_m) for the plot.
With -extrapolate: the settlement error of the ladder (errors.dat of `Allrun -full`) taken
to zero cell size and to an unbounded half-space, both errors being first order (in h and
in a / L): Richardson in h on the two finest 10 m runs, then twice the change from the 10 m
to the 20 m model at their finest common cell size.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from gpicdat import read_columns, read_particles  # noqa: E402

A, E, NU = 1.0, 10e6, 0.3   # punch radius [m] (constant/bodies), soil (constant/materials)
R_MAX = 0.6                 # the compared columns: centres within 0.6 a of the axis


def sadowsky(r, P):
    return P / (2 * math.pi * A * math.sqrt(A * A - r * r)) if r < A else 0.0


def last_time(case):
    times = [d for d in os.listdir(case) if os.path.isfile(os.path.join(case, d, 'particles.vtp'))]
    return max(times, key=float)


def main(case):
    forces = read_columns(os.path.join(case, 'postProcessing', 'forces', '0', 'forces.dat'))
    P = forces['punch:Faxial'][-1]
    s = -forces['punch:dy'][-1]
    s_exact = P * (1 - NU * NU) / (2 * A * E)
    p_mean = P / (math.pi * A * A)

    part = read_particles(os.path.join(case, last_time(case), 'particles.vtp'))
    soil = [k for k, b in enumerate(part['body']) if b == 0]
    h = 4 * part['halfSize'][soil[0]][0]   # 2 x 2 particles a cell
    surface = max(part['initialPosition'][k][1] + part['halfSize'][k][1] for k in soil)
    columns = {}
    for k in soil:
        r, z = part['initialPosition'][k][:2]
        if surface - z < h:   # the top row of cells
            columns.setdefault(int(r / h), []).append((-part['stress'][k][4], sadowsky(r, P)))
    worst = 0.0
    with open(os.path.join(case, 'pressure.dat'), 'w') as out:
        out.write('# r/a p/p_m (top-row column means) p_Sadowsky/p_m (same particles); h = %g m, '
                  'P = %g N, s = %g m, s_Boussinesq = %g m\n' % (h, P, s, s_exact))
        for c in sorted(columns):
            r = (c + 0.5) * h
            if r > 2 * A:
                break
            num = sum(v[0] for v in columns[c]) / len(columns[c])
            ref = sum(v[1] for v in columns[c]) / len(columns[c])
            out.write('%g %g %g\n' % (r / A, num / p_mean, ref / p_mean))
            if r <= R_MAX * A:
                worst = max(worst, abs(num - ref) / p_mean)
        out.write('\n\n# r/a p_Sadowsky/p_m\n')
        for k in range(200):
            r = A * k / 200
            out.write('%g %g\n' % (r / A, sadowsky(r, P) / p_mean))
    print('%.3f %.3f %.6g %.6g' % (100 * (s / s_exact - 1), 100 * worst, P, s))


def extrapolate(path):
    runs = {}
    for line in open(path):
        if not line.startswith('#'):
            w = line.split()
            runs[(float(w[0]), float(w[7]))] = float(w[5])   # (size, h): settlement error
    h10 = sorted(h for (L, h) in runs if L == 10)
    common = sorted(h for (L, h) in runs if L == 20 and (10, h) in runs)
    if len(h10) < 2 or not common:
        return
    fine, coarse = h10[0], h10[1]
    at10 = runs[(10, fine)] + (runs[(10, fine)] - runs[(10, coarse)]) * fine / (coarse - fine)
    truncation = runs[(10, common[0])] - runs[(20, common[0])]   # = e(10) / 2 for e ~ a / L
    print('Settlement error extrapolated: h -> 0 on the 10 m model %.2f %%; the truncation at '
          '10 m %.2f %%, at 20 m %.2f %%; h -> 0 and L -> infinity %.2f %%'
          % (at10, 2 * truncation, truncation, at10 - 2 * truncation))


if __name__ == '__main__':
    if sys.argv[1] == '-extrapolate':
        extrapolate(sys.argv[2])
    else:
        main(sys.argv[1])
