#!/usr/bin/env python3
"""Plane-strain oedometer with Mohr-Coulomb against the closed form of seed appendix H.5.4.

Only eps22 changes (compression, e = -eps22 > 0). With alpha1 = K + 4G/3, alpha2 = K - 2G/3
and N_x = (1 + sin x)/(1 - sin x) the point is elastic, -sigma22 = alpha1 e, until both
edges of the yield surface through sigma11 = sigma33 are reached at
    e_y = 2 c sqrt(N_phi) / (alpha1 - alpha2 N_phi);
then it flows along that edge with the slope d(-sigma22)/de = alpha1 - 2 lambda (alpha1 - alpha2 N_psi),
    lambda = (alpha1 - alpha2 N_phi) / ((alpha1 + alpha2) N_phi N_psi - 2 alpha2 (N_phi + N_psi) + 2 alpha1).
For each test prints: test, psi, steps, yield step, wall time [s] and the largest
|sigma22 - exact| / |exact| in %. With -series writes -eps22 and -sigma22 (computed and exact,
MPa) of both tests to series.dat in the case.
"""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from gpicdat import driver_wall_times  # noqa: E402

# Seed Table 4.4.
K, G, C, PHI = 200e6, 200e6, 1e6, 10.0
PSI = {'associated': 10.0, 'nonAssociated': 0.0}


def flow_factor(angle_deg):
    s = math.sin(math.radians(angle_deg))
    return (1 + s) / (1 - s)


def exact_sigma22(eps22, psi):
    """sigma22 [Pa] (tension positive) at strain eps22 <= 0."""
    a1, a2 = K + 4 * G / 3, K - 2 * G / 3
    n_phi, n_psi = flow_factor(PHI), flow_factor(psi)
    e = -eps22
    e_y = 2 * C * math.sqrt(n_phi) / (a1 - a2 * n_phi)
    if e <= e_y:
        return -a1 * e
    lam = (a1 - a2 * n_phi) / ((a1 + a2) * n_phi * n_psi - 2 * a2 * (n_phi + n_psi) + 2 * a1)
    slope = a1 - 2 * lam * (a1 - a2 * n_psi)
    return -(a1 * e_y + slope * (e - e_y))


def read_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return [float(r['eps22']) for r in rows], [float(r['sigma22']) for r in rows]


case = sys.argv[1]
walls = driver_wall_times(os.path.join(case, 'log.picMaterialTest'))
series = {}
for test, psi in PSI.items():
    eps, sigma = read_csv(os.path.join(case, 'postProcessing', 'picMaterialTest', test + '.csv'))
    exact = [exact_sigma22(e, psi) for e in eps]
    error = max(abs(s - x) / abs(x) for s, x in zip(sigma[1:], exact[1:]))
    # The first step off the elastic line.
    a1 = K + 4 * G / 3
    yield_step = next((i for i, (e, s) in enumerate(zip(eps, sigma))
                       if abs(s - a1 * e) > 1e-6 * abs(a1 * e)), len(eps))
    print(test, int(psi), len(eps) - 1, yield_step, walls.get(test, float('nan')), 100 * error)
    series[test] = (eps, sigma, exact)

if '-series' in sys.argv:
    with open(os.path.join(case, 'series.dat'), 'w') as f:
        f.write('# -eps22 | -sigma22 [MPa]: associated computed, exact; nonAssociated computed, exact\n')
        (eps, s1, x1), (_, s0, x0) = series['associated'], series['nonAssociated']
        for e, *stresses in zip(eps, s1, x1, s0, x0):
            # compression positive; 0.0 - v writes 0 rather than -0
            f.write(' '.join([f'{0.0 - e:.9g}'] + [f'{(0.0 - v) / 1e6:.9g}' for v in stresses]) + '\n')
