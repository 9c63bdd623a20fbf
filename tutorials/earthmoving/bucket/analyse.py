#!/usr/bin/env python3
"""Draft force, free surfaces, PDR maps and stresses of the dragline bucket (seed Case 6.2.6).

The forces function object writes the force of the corn on the bucket (bucket:Fx, bucket:Fy,
postProcessing/forces/*/forces.dat); the seed plots the force of the bucket on the corn,
    F_x1 = -bucket:Fx (the draft force),  F_x2 = -bucket:Fy,
against the bucket's x1 travel (bucket:dx; fig. 6.25, 0 ... 800 mm). F at a travel d is the
trapezoidal time average over the samples with |travel - d| <= 10 mm (the force ripples as
the bucket crosses the cells). Forces are per metre of bucket width: x 0.2 m for the rig [N].

The weighted bucket rides on the corn: over the drag its mean vertical load from the corn,
bucket:Fy, equals its weight m g (m: the mass of its particles, g: constant/g); the error
(Fy - m g) / m g [%] checks the driver and the forces together.

Usage: analyse.py <case> [-series] [-full] [-marks] [-post TAG]
-series writes series.dat (travel [mm], F_x1, F_x2 [N/m]) and prints
        F(50 mm) F(100 mm) F(end) Fy_mean m_g error_% Fx1_mean   ('-' where not reached);
        F(end): over the last 20 mm; Fy_mean, Fx1_mean: bucket:Fy and F_x1 over 50 mm ... the end.
-full   prints F_x1 every 100 mm, the seed's statement at 800 mm and the corn gone over the
        grid's top (the spill function object), if any.
-marks  prints the travel reached [mm], then "mm F_x1" for every 100 mm mark reached (a
        drag the stability guard stopped included: what it reached).
-post   free surfaces every 100 mm (picFreeSurface; fig. 6.30) -> surface-TAG.png and .dat;
        PDR over 10 mm after 100, 500, 800 mm (picDisplacementRatio; figs. 6.32-6.34, the
        seed's colour bands) -> pdr-TAG-<mm>.png; normal and shear stress along the inside of
        the bucket at the last 100 mm mark reached (picForces -surface per face; figs. 6.35,
        6.36: the seed's maxima at 800 mm, nonpolar 15.1 and 3.5 kPa) -> stress-TAG.png, .dat.
"""
import csv
import glob
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ.get('GPIC_DIR', '../../..'), 'etc', 'python'))
from gpicdat import read_particles, tool_forces, window_mean  # noqa: E402

WINDOW = 0.01


def at(t, f, travel, d):
    """Mean of f over |travel - d| <= WINDOW, or None when the run did not get there."""
    if not travel or max(travel) < d - 0.001:   # the last write may stop just short of d
        return None
    return window_mean(t, f, [abs(x - d) <= WINDOW + 1e-9 for x in travel])


def fmt(v):
    return '-' if v is None else f'{v:.1f}'


def case_geometry(case):
    """(wall thickness, the bucket's back x0, the corn's surface y0) [m], as Allrun made them."""
    grid = re.sub(r'//[^\n]*', '', open(os.path.join(case, 'constant', 'grid')).read())
    cell = re.search(r'cellSize\s+([^;]+);', grid).group(1).strip()
    t = 0.015 if cell.startswith('(') else max(0.015, float(cell))
    control = open(os.path.join(case, 'system', 'controlDict')).read()
    x0, y0 = map(float, re.search(r'CofR \(([^)]*)\)', control).group(1).split())
    return t, x0, y0


def written(case):
    """Written time directories (name, time), in time order."""
    out = []
    for d in glob.glob(os.path.join(case, '[0-9]*')):
        name = os.path.basename(d)
        if re.fullmatch(r'[0-9.e+-]+', name) and os.path.isfile(os.path.join(d, 'particles.vtp')):
            out.append((name, float(name)))
    return sorted(out, key=lambda n: n[1])


def pose(t, dx, dy, time):
    """The bucket's displacement at the forces sample nearest to `time`."""
    k = min(range(len(t)), key=lambda i: abs(t[i] - time))
    return dx[k], dy[k]


def run(args, case):
    return subprocess.run(args + ['-case', case], capture_output=True, text=True)


def post(case, tag, t, travel, dy):
    times = written(case)
    travel_at = [(name, time, pose(t, travel, dy, time)) for name, time in times]
    marks = {}
    for mm in range(100, 900, 100):
        name, time, (x, y) = min(travel_at, key=lambda w: abs(w[2][0] - mm * 1e-3))
        if abs(x - mm * 1e-3) <= 0.006:
            marks[mm] = (name, time, x, y)
    if not marks:
        print('post: no written time at 100 mm of travel or more')
        return
    # Free surfaces (the corn only: body 0)
    out = run(['picFreeSurface', '-times', ' '.join(m[0] for m in marks.values()), '-bodies', '0'], case)
    if out.returncode == 0:
        blocks = {}
        for r in csv.DictReader(open(os.path.join(case, 'postProcessing', 'picFreeSurface', 'surface.csv'))):
            blocks.setdefault(float(r['time']), []).append((float(r['x1']), float(r['x2'])))
        with open(f'surface-{tag}.dat', 'w') as f:
            f.write('# free surface of the corn: x1 [m], x2 [m]; one block per 100 mm of travel\n')
            for mm, (name, time, x, y) in marks.items():
                rows = blocks.get(min(blocks, key=lambda b: abs(b - time)), [])
                f.write(f'# travel {mm} mm ({name} s)\n')
                f.writelines(f'{a:.4f} {b:.4f}\n' for a, b in sorted(rows))
                f.write('\n\n')
        subprocess.run(['gnuplot', '-e', f"data='surface-{tag}.dat'; out='surface-{tag}.png'; n={len(marks)}; "
                        f"x0={case_geometry(case)[1]}; name='{tag}'", os.path.join(HERE, 'surface.gp')], check=False)
        print('free surfaces at ' + ', '.join(f'{mm} mm' for mm in marks) + f': surface-{tag}.png')
    else:
        print('picFreeSurface failed: ' + out.stderr.strip().splitlines()[-1])
    # PDR over the next 10 mm after 100, 500, 800 mm (seed: 10 ... 15 mm after zeroing)
    for mm in (100, 500, 800):
        if mm not in marks:
            continue
        name, time, x, _ = marks[mm]
        later = [w for w in travel_at if w[1] > time and 0.0095 <= w[2][0] - x <= 0.016]
        if not later:
            continue
        out = run(['picDisplacementRatio', '-from', name, '-to', later[0][0], '-tool', 'bucket'], case)
        if out.returncode != 0:
            print('picDisplacementRatio failed: ' + out.stderr.strip().splitlines()[-1])
            continue
        data = os.path.join(case, 'postProcessing', 'picDisplacementRatio', f'{name}-{later[0][0]}', 'pdr.csv')
        outline = bucket_now(case, x, marks[mm][3])
        subprocess.run(['gnuplot', '-e', f"data='{data}'; bucket='{outline}'; out='pdr-{tag}-{mm}.png'; "
                        f"name='{tag}, {mm} ... {mm + round((later[0][2][0] - x) * 1e3)} mm'",
                        os.path.join(HERE, 'pdrMap.gp')], check=False)
        print(f'PDR after {mm} mm: pdr-{tag}-{mm}.png')
    # Stresses along the inside at the last mark
    mm = max(marks)
    name, time, x, y = marks[mm]
    wall, x0, y0 = case_geometry(case)
    faces = subprocess.run([sys.executable, os.path.join(HERE, 'bucketProfile.py'), str(wall), str(x0 + x),
                            str(y0 + y), '-faces'], capture_output=True, text=True, check=True).stdout.split('\n')
    rows, s0 = [], 0.0
    for k, face in enumerate(f for f in faces if f.strip()):
        xa, ya, xb, yb = map(float, face.split())
        out = run(['picForces', '-surface', f'({xa} {ya}) ({xb} {yb})', '-time', name], case)
        length = ((xb - xa) ** 2 + (yb - ya) ** 2) ** 0.5
        path = os.path.join(case, 'postProcessing', 'picForces', f'surface_{name}.csv')
        if out.returncode == 0 and os.path.isfile(path):
            for r in csv.DictReader(open(path)):
                rows.append((s0 + float(r['s']), k, float(r['normalStress']), float(r['shearStress'])))
        s0 += length
    with open(os.path.join(case, 'stress.dat'), 'w') as f:
        f.write(f'# stresses on the inside of the bucket at {mm} mm ({name} s), from the tooth tip (s = 0)\n')
        f.write('# s_mm face normal_kPa shear_kPa\n')
        for s, k, n, tau in rows:
            f.write(f'{s * 1e3:.1f} {k} {n * 1e-3:.3f} {tau * 1e-3:.3f}\n')
    shutil.copy(os.path.join(case, 'stress.dat'), f'stress-{tag}.dat')
    if rows:
        n = max(rows, key=lambda r: r[2])
        tau = max(rows, key=lambda r: abs(r[3]))
        print(f'stresses inside the bucket at {mm} mm: max normal {n[2] * 1e-3:.1f} kPa at s = {n[0] * 1e3:.0f} mm, '
              f'max |shear| {abs(tau[3]) * 1e-3:.1f} kPa at s = {tau[0] * 1e3:.0f} mm (tooth: s < 40 mm; '
              f'seed at 800 mm: nonpolar 15.1, 3.5 kPa; polar 9.8, 2.3 kPa; on the tooth)')
        subprocess.run(['gnuplot', '-e', f"data='stress-{tag}.dat'; out='stress-{tag}.png'; name='{tag}, {mm} mm'",
                        os.path.join(HERE, 'stress.gp')], check=False)


def bucket_now(case, x, y):
    """Writes the bucket's outline, moved by (x, y), for the PDR maps; returns its path."""
    wall, x0, y0 = case_geometry(case)
    poly = subprocess.run([sys.executable, os.path.join(HERE, 'bucketProfile.py'), str(wall), str(x0 + x),
                           str(y0 + y)], capture_output=True, text=True, check=True).stdout
    pts = re.findall(r'\(([-0-9.e]+) ([-0-9.e]+)\)', poly)
    path = os.path.join(case, 'bucketNow.dat')
    with open(path, 'w') as f:
        for px, py in pts + pts[:1]:
            f.write(f'{px},{py}\n')
    return path


def main():
    case = sys.argv[1]
    t, fx, fy, travel = tool_forces(case, 'bucket')
    _, _, _, dy = tool_forces_dy(case)
    fx1 = [-f for f in fx]
    if '-series' in sys.argv:
        with open(os.path.join(case, 'series.dat'), 'w') as f:
            f.write('# travel_mm Fx1 Fx2 [N/m] (the force of the bucket on the corn)\n')
            for d, a, b in zip(travel, fx1, fy):
                if d > 0:
                    f.write(f'{d * 1e3:.4f} {a:.2f} {-b:.2f}\n')
        part = read_particles(os.path.join(case, '0', 'particles.vtp'))
        mass = sum(m for b, m in zip(part['body'], part['mass']) if b == 1)
        g = float(re.search(r'value\s*\(\s*\S+\s+(\S+)\s*\)', open(os.path.join(case, 'constant', 'g')).read()).group(1))
        mg = -mass * g
        end = max(travel)
        fy_mean = window_mean(t, fy, [x >= 0.05 for x in travel]) if end > 0.06 else None
        err = '-' if fy_mean is None else f'{(fy_mean - mg) / mg * 100:.2f}'
        fx1_mean = window_mean(t, fx1, [x >= 0.05 for x in travel]) if end > 0.06 else None
        print(f'{fmt(at(t, fx1, travel, 0.05))} {fmt(at(t, fx1, travel, 0.1))} '
              f'{fmt(at(t, fx1, travel, end - WINDOW))} {fmt(fy_mean)} {mg:.1f} {err} {fmt(fx1_mean)}')
    if '-full' in sys.argv:
        values = [(mm, at(t, fx1, travel, mm * 1e-3 - (WINDOW if mm == 800 else 0))) for mm in range(100, 900, 100)]
        print('draft force F_x1 [N/m] at ' + ', '.join(f'{mm}: {fmt(v)}' for mm, v in values))
        print('seed: nonpolar = measured up to 600 mm, -12 % at 800 mm; polar below both')
        gone = spilled(case)
        if gone:
            print(f'corn gone over the grid\'s top (outflow): {gone:.4g} kg/m')
    if '-marks' in sys.argv:
        print(f'{max(travel) * 1e3:.0f}')
        for mm in range(100, 900, 100):
            value = at(t, fx1, travel, mm * 1e-3 - (WINDOW if mm == 800 else 0))
            if value is not None:
                print(mm, fmt(value))
    if '-post' in sys.argv:
        post(case, sys.argv[sys.argv.index('-post') + 1], t, travel, dy)


def spilled(case):
    """Corn gone through the open top [kg/m]: the spill function object's last line."""
    files = sorted(glob.glob(os.path.join(case, 'postProcessing', 'spill', '*', 'massFlow.dat')))
    lines = [l.split() for l in open(files[-1]) if l.strip() and not l.startswith('#')] if files else []
    return float(lines[-1][2]) if lines else 0.0


def tool_forces_dy(case):
    """(time, -, -, dy) of the bucket: its vertical travel, for the stresses' face positions."""
    from gpicdat import read_columns
    t, dy = [], []
    for path in sorted(glob.glob(os.path.join(case, 'postProcessing', 'forces', '*', 'forces.dat')),
                       key=lambda p: float(os.path.basename(os.path.dirname(p)))):
        c = read_columns(path)
        start = c['time'][0] if c['time'] else float('inf')
        while t and t[-1] >= start:
            t.pop()
            dy.pop()
        t += c['time']
        dy += c['bucket:dy']
    return t, None, None, dy


if __name__ == '__main__':
    main()
