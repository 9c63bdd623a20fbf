#!/usr/bin/env python3
"""Seed case 4.4 with the contact model: where the total energy is lost, and momentum.

From bodyMotion.dat (energy E = kinetic + stress work; x1 momenta of both disks):
    loss  = (E0 - E(3 s)) / E0                         lost by the time the disks are apart
    drift = max |E(t) - E(3 s)| / E0 for t >= 3 s       change after separation
    sum   = max |px(upperLeft) + px(lowerRight)| / p0   total momentum (zero exactly)
and from log.picSolver the contact pass's share of the timed passes.
Prints: loss_% drift_% momentum_% contact_share_% (- without a contact pass).
With -series writes time, Ek, Es, E to series.dat in the case.
"""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from gpicdat import read_columns  # noqa: E402

case = sys.argv[1]
col = read_columns(os.path.join(case, 'postProcessing/motion/0/bodyMotion.dat'))
t, E = col['time'], col['E']
E0, p0 = E[0], abs(col['upperLeft:px'][0])
apart = [e for ti, e in zip(t, E) if ti >= 3.0]
loss = (E0 - apart[0]) / E0 * 100
drift = max(abs(e - apart[0]) for e in apart) / E0 * 100
total = max(abs(a + b) for a, b in zip(col['upperLeft:px'], col['lowerRight:px'])) / p0 * 100
share = '-'
with open(os.path.join(case, 'log.picSolver')) as f:
    for line in f:
        m = re.match(r'\s+contact\s+\S+ s\s+(\S+) %', line)
        if m:
            share = m.group(1)
print(f'{loss:.4g} {drift:.3g} {total:.2g} {share}')
if '-series' in sys.argv:
    with open(os.path.join(case, 'series.dat'), 'w') as f:
        f.write('# time Ek Es E\n')
        for row in zip(t, col['Ek'], col['Es'], E):
            f.write(' '.join(str(v) for v in row) + '\n')
