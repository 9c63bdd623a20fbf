#!/usr/bin/env python3
"""Plane silo discharge (seed 6.3): mass in the silo against time and the mean flow rate
against Beverloo et al. (1961).

The massFlow function object (factor 2 x 0.73: the whole 0.73 m deep glass silo of the half
model) writes the mass in the silo [kg]. The flow rate is the least-squares slope of that
mass against time from 0.2 s after the opening (the flow has built up; the seed's curves
are straight from there) until the mass falls to 30 % of the initial mass or the run ends.

Beverloo's rate through a slot of width w per metre of silo depth (seed eq. 4.6.1, the
constant 45 in kg/min), times the silo's depth:
    W = 45 rho sqrt(2 g) (w - 0.7 d)^1.5 / 60 x 0.73   [kg/s]
with rho the (constant) bulk density and d the grain size (corn d50 = 10 mm, sand 1 mm).
The outlet opens nodes of the grid's bottom side, so the orifice the grid sees ends on the
last open node: w_h = 2 x (that node's x1); Allrun puts the opening's end on the node
nearest w/2. The reference is W(w_h); W(w) is printed beside it.

Usage: analyse.py <case> -rho R -d D -w W [-series]
Prints: rate [kg/s], W(w_h), error against W(w_h) [%], W(w), w_h [m], initial mass [kg],
opening time [s], discharge time run [s], wall time of the discharge [s], particles at the
start, steps and wall time of the run, 1 when the discharge stage finished (0: the run
stopped inside it; the rate is then from the samples before the stop), and the mass left at
the end in % of the fill. -series writes series.dat in the case: time after the opening [s], mass in the silo
[kg], the Beverloo line m(0.2 s) - W(w_h) (t - 0.2 s) [kg] (NaN before 0.2 s).
"""
import glob
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
import gpicdat  # noqa: E402
from gpicdat import read_columns  # noqa: E402

G, DEPTH, START, LAST = 9.81, 0.73, 0.2, 0.3


def beverloo(rho, w, d):
    return 45 * rho * math.sqrt(2 * G) * max(w - 0.7 * d, 0.0) ** 1.5 / 60 * DEPTH


def discharge_stage(case):
    """(start time, end time) of the discharge stage from postProcessing/stages.dat (the
    fill's end when the run stopped inside the discharge; end None then)."""
    with open(os.path.join(case, 'postProcessing', 'stages.dat')) as f:
        for line in f:
            words = line.split()
            if words and not words[0].startswith('#'):
                if words[5] == 'discharge':
                    return float(words[1]), float(words[2])
                if words[5] == 'fill':
                    fill_end = float(words[2])
    if 'fill_end' in locals():
        return fill_end, None
    raise RuntimeError('no discharge in ' + case + '/postProcessing/stages.dat')


def opened_width(case):
    """w_h = 2 x the x1 of the last node of the bottom side inside the opening."""
    text = re.sub(r'//[^\n]*', '', open(os.path.join(case, 'constant', 'grid')).read())
    size = re.search(r'cellSize\s+\(\s*(\S+)\s+\S+\s*\)', text)
    dx = float(size.group(1)) if size else float(re.search(r'cellSize\s+(\S+);', text).group(1))
    end = float(re.search(r'bottom[^}]*opening\s+\(\s*\S+\s+(\S+)\s*\)', text).group(1))
    return 2 * math.floor(end / dx + 1e-9) * dx


def progress(log):
    """(time, step, wall) of the solver's progress lines and of its End line."""
    points = [(0.0, 0, 0.0)]
    with open(log) as f:
        for line in f:
            m = re.match(r't = (\S+)\s+step\s+(\d+)\s+dt\s+\S+\s+wall\s+(\S+) s', line)
            if m:
                points.append((float(m.group(1)), int(m.group(2)), float(m.group(3))))
            m = re.match(r'End: t = (\S+), (\d+) steps, \d+ particles, wall (\S+) s', line)
            if m:
                points.append((float(m.group(1)), int(m.group(2)), float(m.group(3))))
    return points


def wall_at(log, t):
    """Wall time [s] at run time t, interpolated between the solver's progress lines."""
    points = [(t, w) for t, _, w in progress(log)]
    for (t0, w0), (t1, w1) in zip(points, points[1:]):
        if t0 <= t <= t1:
            return w0 + (w1 - w0) * (t - t0) / (t1 - t0) if t1 > t0 else w0
    return points[-1][1]


def slope(ts, ms):
    n = len(ts)
    tm, mm = sum(ts) / n, sum(ms) / n
    return sum((t - tm) * (m - mm) for t, m in zip(ts, ms)) / sum((t - tm) ** 2 for t in ts)


case = sys.argv[1]
rho, = gpicdat.option(sys.argv, '-rho', 1, [None])
d, = gpicdat.option(sys.argv, '-d', 1, [None])
w, = gpicdat.option(sys.argv, '-w', 1, [None])
if None in (rho, d, w):
    sys.exit('usage: analyse.py <case> -rho R -d D -w W [-series]')
t0, t1 = discharge_stage(case)
finished = t1 is not None
files = sorted(glob.glob(os.path.join(case, 'postProcessing', 'silo', '*', 'massFlow.dat')),
               key=lambda p: float(os.path.basename(os.path.dirname(p))))
times, mass = [], []
for path in files:   # a restart adds a directory; its lines replace the earlier ones from its start
    c = read_columns(path)
    start = c['time'][0] if c['time'] else float('inf')
    while times and times[-1] >= start:
        times.pop(), mass.pop()
    times += c['time']
    mass += c['mass']
if not finished:   # stopped inside the discharge: up to its last line
    t1 = times[-1]
m0 = next(m for t, m in zip(times, mass) if t >= t0 - 1e-12)
window = [(t, m) for t, m in zip(times, mass) if t >= t0 + START and m >= LAST * m0]
if len(window) < 3:
    sys.exit(f'{case}: too few samples of the mass after {START} s of discharge')
rate = -slope([t for t, _ in window], [m for _, m in window])
w_h = opened_width(case)
ref, nominal = beverloo(rho, w_h, d), beverloo(rho, w, d)
wall = wall_at(os.path.join(case, 'log.picSolver'), t1) - wall_at(os.path.join(case, 'log.picSolver'), t0)
particles = 0
with open(os.path.join(case, 'log.picInit')) as f:
    for line in f:
        if 'particles in' in line:
            particles = int(line.split(':')[1].split()[0])
_, steps, wall_all = progress(os.path.join(case, 'log.picSolver'))[-1]
print(f'{rate:.3f} {ref:.3f} {100 * (rate - ref) / ref:.2f} {nominal:.3f} {w_h:.6g} {m0:.3f} '
      f'{t0:.6g} {t1 - t0:.6g} {wall:.1f} {particles} {steps} {wall_all:.1f} {int(finished)} '
      f'{100 * mass[-1] / m0:.1f}')
if '-series' in sys.argv:
    ms = window[0][1]
    with open(os.path.join(case, 'series.dat'), 'w') as f:
        f.write(f'# time after opening [s], mass in silo [kg], Beverloo W(w_h) = {ref:.3f} kg/s '
                f'from the mass at {START} s [kg]; rate {rate:.3f} kg/s\n')
        for t, m in zip(times, mass):
            if t >= t0 - 1e-12:
                line = max(ms - ref * (t - t0 - START), 0.0) if t >= t0 + START else float('nan')
                f.write(f'{t - t0:.6g} {m:.6g} {line:.6g}\n')
