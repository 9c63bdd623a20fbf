"""The discharge of a silo for tutorial scripts (standard library only): the mass in the silo
from a massFlow function object against time, its mean slope after the flow has built up,
and Beverloo's rate at the orifice the grid opens. Used by tutorials/earthmoving/silos (a
slot, plane), tutorials/earthmoving/circularSilo (a circular orifice, axisymmetric) and
tutorials/earthmoving/circularSilo3D (the same in 3D)."""
import math
import os
import re
import sys

from gpicdat import option, read_series

START, LAST = 0.2, 0.3   # the window: from START s after the opening to LAST of the fill


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



def analyse(argv, beverloo, width='w', opened=opened_width):
    """The command line of a silo tutorial's analyse.py: <case> -rho R -d D -w W [-series].
    `beverloo(rho, w, d)` is the reference rate [kg/s] through an orifice of width (or
    diameter) w; `width` names it in series.dat; `opened(case)` is the width the grid opens
    (default: a plane side's stretch, opened_width). Prints the line the Allrun reads."""
    case = argv[1]
    rho, = option(argv, '-rho', 1, [None])
    d, = option(argv, '-d', 1, [None])
    w, = option(argv, '-w', 1, [None])
    if None in (rho, d, w):
        sys.exit('usage: analyse.py <case> -rho R -d D -w W [-series]')
    t0, t1 = discharge_stage(case)
    finished = t1 is not None
    series = read_series(case, 'silo', 'massFlow.dat')   # a restart's lines replace the earlier ones
    times, mass = series['time'], series['mass']
    if not finished:   # stopped inside the discharge: up to its last line
        t1 = times[-1]
    m0 = next(m for t, m in zip(times, mass) if t >= t0 - 1e-12)
    window = [(t, m) for t, m in zip(times, mass) if t >= t0 + START and m >= LAST * m0]
    if len(window) < 3:
        sys.exit(f'{case}: too few samples of the mass after {START} s of discharge')
    rate = -slope([t for t, _ in window], [m for _, m in window])
    w_h = opened(case)
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
    if '-series' in argv:
        ms = window[0][1]
        with open(os.path.join(case, 'series.dat'), 'w') as f:
            f.write(f'# time after opening [s], mass in silo [kg], Beverloo W({width}_h) = {ref:.3f} kg/s '
                    f'from the mass at {START} s [kg]; rate {rate:.3f} kg/s\n')
            for t, m in zip(times, mass):
                if t >= t0 - 1e-12:
                    line = max(ms - ref * (t - t0 - START), 0.0) if t >= t0 + START else float('nan')
                    f.write(f'{t - t0:.6g} {m:.6g} {line:.6g}\n')
