#!/usr/bin/env python3
"""Silo discharge (seed 4.6): mass flow rate against Beverloo et al. (1961).

Beverloo's rate through a slot of width D per metre of silo depth (seed eq. 4.6.1), with
the constant 45 in kg/min:
    W = 45 rho sqrt(2 g) (D - 0.7 d)^1.5 / 60   [kg/s per m]
For rho 1500 kg/m^3, D = 0.1 m: 157.6 kg/s (d/D = 0) and 141.3 kg/s (d/D = 0.1), the two
lines of the seed's fig. 4.31. The massFlow function object (factor 2: the whole silo of
the half model) gives the outflow rate; the discharge starts when the `discharge` stage
begins (postProcessing/stages.dat). The steady rate is the mass gone between 0.15 and 0.45 s
after the opening over that time: the flow builds up in the first 0.1 s, and the silo is
about half empty at 0.45 s.
Usage: analyse.py <case> [-series]
Prints: steady rate [kg/s], error against d/D = 0 and against d/D = 0.1 [%], opening time [s],
and the particles at the start. With -series writes time after opening, rate and the
Beverloo lines to series.dat in the case.
"""
import glob
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from gpicdat import read_columns  # noqa: E402

RHO, G, D = 1500.0, 9.81, 0.1
WINDOW = (0.15, 0.45)


def beverloo(d_over_D):
    return 45 * RHO * math.sqrt(2 * G) * (D - 0.7 * d_over_D * D) ** 1.5 / 60


def opening_time(case):
    with open(os.path.join(case, 'postProcessing', 'stages.dat')) as f:
        for line in f:
            words = line.split()
            if words and not words[0].startswith('#') and words[5] == 'discharge':
                return float(words[1])
    raise RuntimeError('no discharge stage in ' + case + '/postProcessing/stages.dat')


def mass_gone(times, out, t):
    """Mass gone at time t, interpolated linearly between the lines."""
    for k in range(1, len(times)):
        if times[k] >= t:
            w = (t - times[k - 1]) / (times[k] - times[k - 1])
            return out[k - 1] + w * (out[k] - out[k - 1])
    raise RuntimeError(f'the run ended before t = {t} s')


case = sys.argv[1]
t0 = opening_time(case)
dat = read_columns(sorted(glob.glob(os.path.join(case, 'postProcessing', 'silo', '*', 'massFlow.dat')))[-1])
times, out = dat['time'], dat['out']
rate = (mass_gone(times, out, t0 + WINDOW[1]) - mass_gone(times, out, t0 + WINDOW[0])) / (WINDOW[1] - WINDOW[0])
w0, w1 = beverloo(0.0), beverloo(0.1)
particles = 0
with open(os.path.join(case, 'log.picInit')) as f:
    for line in f:
        if 'particles in' in line:
            particles = int(line.split(':')[1].split()[0])
print(f'{rate:.2f} {100 * (rate - w0) / w0:.2f} {100 * (rate - w1) / w1:.2f} {t0:.6g} {particles}')
if '-series' in sys.argv:
    with open(os.path.join(case, 'series.dat'), 'w') as f:
        f.write(f'# time after opening [s], outflow rate [kg/s], Beverloo d/D = 0 and 0.1 [kg/s]; steady {rate:.2f}\n')
        for t, r in zip(times, dat['outflowRate']):
            if t > t0:
                f.write(f'{t - t0:.6g} {r} {w0:.2f} {w1:.2f}\n')
