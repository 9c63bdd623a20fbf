#!/usr/bin/env python3
"""The muI material point (picMaterialTest) against its closed forms.

Shear at a set rate gammaDot from p = 1 kPa: the steady state carries tau/p = mu(I) with
I = gammaDot d / sqrt(p / rhoS) and mu(I) = muS + (mu2 - muS) / (I0 / I + 1) (Jop, Forterre &
Pouliquen 2006), tau = sqrt(J2) = q / sqrt(3). Without the rigid spin the deviator keeps its
axes and the steady state is exact; with it (spin100) the Jaumann rotation adds normal stress
differences of order tau / G, and tau / p departs from mu(I) by that order.

Separation: out, the point is elastic (and may flow: in plane strain the unloading shears
it while its pressure falls), then separated (trial not compressive, stress-free), then
disconnected (m/V < rhoC); back, disconnected until m/V >= rhoC, then elastic with the
stress of the compression taken since: sigma = D (sum of those strain increments). The
volume follows the driver's det(I + dt L) step by step, so the step of re-forming is exact.

Prints per test: test, gammaDot [1/s] (0 for separation), steps, final yieldState, wall [s],
error [%]: |tau/p - mu(I)| / mu(I), or the largest |sigma - closed form| / |sigma11 closed form|
(and exits 1 on a wrong state sequence). With -series writes muI.dat and separation.dat.
"""
import csv
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from gpicdat import driver_wall_times  # noqa: E402

MU_S, MU_2, I_0, D, RHO_S = 0.3819, 0.6435, 0.278, 0.5e-3, 2450.0
RHO, RHO_C, E, NU = 1500.0, 1485.0, 1e7, 0.3
K, G = E / (3 * (1 - 2 * NU)), E / (2 * (1 + NU))
GAMMA = {'rate10': 0.01, 'rate40': 0.04, 'rate100': 0.1, 'rate400': 0.4, 'rate1500': 1.5, 'spin100': 0.1}
SEPARATION_STRAIN = 0.02  # eps11 = eps22 out and back


def mu(I):
    return MU_S + (MU_2 - MU_S) / (I_0 / I + 1)


def keyword(text, key):
    return re.search(r'^\s*' + key + r'\s+([^;\s]+)\s*;', text, re.M).group(1)


def rows(case, test):
    with open(os.path.join(case, 'postProcessing', 'picMaterialTest', test + '.csv')) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def shear(case, test, steps, dt):
    r = rows(case, test)[-1]
    p, tau = r['p'], r['q'] / math.sqrt(3)
    rate = GAMMA[test] / (steps * dt)
    I = rate * D / math.sqrt(p / RHO_S)
    return rate, r['yieldState'], abs(tau / p - mu(I)) / mu(I), (I, tau / p)


def separation(case, steps):
    """Largest stress error in % of the closed-form sigma11, and the states seen, in order."""
    r = rows(case, 'separation')
    half = steps // 2
    a = SEPARATION_STRAIN / half
    a1, a2 = K + 4 * G / 3, K - 2 * G / 3
    V, m, taken = 1.0, RHO, 0.0
    states, series = [], []
    for n in range(1, steps + 1):
        de = a if n <= half else -a
        V *= (1.0 + de) * (1.0 + de) - 0.0  # the driver's det(I + dt L), plane strain
        connected = not (m < RHO_C * V)
        if n > half and connected:
            taken += de
        state = int(r[n]['yieldState'])
        if not states or states[-1] != state:
            states.append(state)
        if n > half and (state == 0) != connected:
            print(f'separation: step {n}: state {state} but m/V = {m / V:.6f}', file=sys.stderr)
            sys.exit(1)
        series.append((n, m / V, r[n]['p']))
    exact = {'sigma11': (a1 + a2) * taken, 'sigma22': (a1 + a2) * taken, 'sigma33': 2 * a2 * taken, 'sigma12': 0.0}
    error = max(abs(r[-1][k] - v) for k, v in exact.items()) / abs(exact['sigma11'])
    # Out: elastic, then (the unloading of plane strain sheared the point: tau grows as p
    # falls) flowing, then separated and disconnected; back: disconnected, then elastic.
    while states and states[0] in (0, 1):
        states.pop(0)
    if states != [2, 5, 0]:
        print(f'separation: states {states} after the first elastic and flowing steps; expected '
              'separated, disconnected, elastic', file=sys.stderr)
        sys.exit(1)
    return r[-1]['yieldState'], error, series


case = sys.argv[1]
dictionary = open(os.path.join(case, 'system', 'materialTestDict')).read()
steps, dt = int(keyword(dictionary, 'steps')), float(keyword(dictionary, 'deltaT'))
walls = driver_wall_times(os.path.join(case, 'log.picMaterialTest'))
points = {}
for test in GAMMA:
    rate, state, error, point = shear(case, test, steps, dt)
    points[test] = point
    print(test, f'{rate:g}', steps, int(state), walls.get(test, float('nan')), 100 * error)
state, error, series = separation(case, steps)
print('separation', 0, steps, int(state), walls.get('separation', float('nan')), 100 * error)

if '-series' in sys.argv:
    with open(os.path.join(case, 'muI.dat'), 'w') as f:
        f.write('# test I tau/p\n')
        for test, (I, ratio) in points.items():
            f.write(f'{test} {I:.9g} {ratio:.9g}\n')
    with open(os.path.join(case, 'separation.dat'), 'w') as f:
        f.write('# step density[kg/m^3] p[kPa]\n')
        for n, rho, p in series:
            f.write(f'{n} {rho:.9g} {p / 1e3:.9g}\n')
