"""Reading granular-pic output for tutorial scripts (standard library only)."""
import glob
import os
import re
import struct


def read_columns(path):
    """Columns of a postProcessing .dat file, keyed by the names of its last '#' line."""
    names, columns = [], {}
    with open(path) as f:
        for line in f:
            if line.startswith('#'):
                names = line[1:].split()
                columns = {n: [] for n in names}
                continue
            for name, value in zip(names, line.split()):
                columns[name].append(float(value))
    return columns


def driver_wall_times(log_path):
    """Wall time [s] by test from picMaterialTest's summary lines."""
    times = {}
    with open(log_path) as f:
        for line in f:
            m = re.match(r'(\w+) \(.*, wall (\S+) s$', line.strip())
            if m:
                times[m.group(1)] = float(m.group(2))
    return times


def run_summary(log_path):
    """(particles, steps, wall seconds) from the 'End:' line of a picSolver log."""
    with open(log_path) as f:
        for line in f:
            m = re.match(r'End: t = \S+, (\d+) steps, (\d+) particles, wall (\S+) s', line)
            if m:
                return int(m.group(2)), int(m.group(1)), float(m.group(3))
    raise RuntimeError('no End: line in ' + log_path + ' (did the run fail?)')


def run_reached(log_path):
    """(particles, steps, wall seconds) of a picSolver run, finished or not: the 'End:' line,
    else the case line's particle count and the last progress line's step and wall time."""
    try:
        return run_summary(log_path)
    except RuntimeError:
        pass
    particles = steps = wall = None
    with open(log_path) as f:
        for line in f:
            m = re.match(r'Case \S+: (\d+) particles', line)
            if m:
                particles = int(m.group(1))
            m = re.match(r't = \S+\s+step (\d+)\s+dt \S+\s+wall\s+(\S+) s', line)
            if m:
                steps, wall = int(m.group(1)), float(m.group(2))
    if None in (particles, steps, wall):
        raise RuntimeError('no progress line in ' + log_path)
    return particles, steps, wall


def segment_wall(log_path):
    """Wall seconds of one segment of a run: its End line, its stop line ('run stopped by
    SIGTERM at t = ... (step N, wall W s)'), else its last progress line (cut off)."""
    try:
        return run_summary(log_path)[2]
    except RuntimeError:
        pass
    with open(log_path) as f:
        for line in f:
            m = re.search(r'run stopped by \S+ at t = \S+ s \(step \d+, wall (\S+) s\)', line)
            if m:
                return float(m.group(1))
    return run_reached(log_path)[2]


def run_in_segments(case):
    """(particles, steps, wall seconds) of a run made in segments: picSolver stopped (a
    signal, the end of a sitting) and restarted from its last time directory, the earlier
    logs kept as log.picSolver.1, .2, ... before log.picSolver, the last. Steps count from
    the run's first step (the time index it carried on from, plus the last segment's);
    wall adds the segments' (a segment cut off between writes counts its lost steps too).
    A run of one segment gives what run_reached gives."""
    earlier = sorted(glob.glob(os.path.join(case, 'log.picSolver.[0-9]*')),
                     key=lambda p: int(p.rsplit('.', 1)[1]))
    last = os.path.join(case, 'log.picSolver')
    wall = sum(segment_wall(log) for log in earlier)
    try:
        particles, steps, last_wall = run_summary(last)
    except RuntimeError:  # not finished: its progress lines count from the run's first step
        particles, steps, last_wall = run_reached(last)
        return particles, steps, round(wall + last_wall, 3)
    start = None
    with open(last) as f:
        for line in f:
            m = re.match(r'Case \S+: .*starting at t = \S+ \((\S+)\)', line)
            if m:
                start = m.group(1)
    index = 0
    time_file = os.path.join(case, start, 'uniform', 'time') if start else ''
    if time_file and os.path.exists(time_file):
        m = re.search(r'index\s+(\d+);', open(time_file).read())
        index = int(m.group(1)) if m else 0
    return particles, index + steps, round(wall + last_wall, 3)


def run_status(case):
    """(finished 1/0, particles, steps, wall seconds) of the picSolver run logged in
    <case>/log.picSolver; a run stopped before its first progress line: its start's count,
    the step it stopped at and no wall time."""
    log_path = os.path.join(case, 'log.picSolver')
    try:
        run_summary(log_path)
        finished = 1
    except RuntimeError:
        finished = 0
    try:
        particles, steps, wall = run_reached(log_path)
    except RuntimeError:
        log = open(log_path).read()
        particles = int(re.search(r'Case \S+: (\d+) particles', log).group(1))
        steps = int(re.search(r'\(step (\d+)\)', log).group(1))
        wall = 0.0
    return finished, particles, steps, wall


def last_state(case):
    """The newest time directory of `case` holding particles: (its name, read_particles of it)."""
    times = sorted((t for t in os.listdir(case) if t[0].isdigit()
                    and os.path.isfile(os.path.join(case, t, 'particles.vtp'))), key=float)
    return times[-1], read_particles(os.path.join(case, times[-1], 'particles.vtp'))


def case_entries(path, name):
    """Keyword values of the sub-dictionary `name` of a case file (or of the file itself)."""
    text = re.sub(r'//[^\n]*', '', open(path).read())
    if name:
        text = re.search(r'\b' + name + r'\s*\{([^}]*)\}', text).group(1)
    return dict(re.findall(r'(\w+)\s+([^;\s]+)\s*;', text))


def tool_depth(case):
    """How deep a tool reaches into the material at time 0 [m]: the top of body 0's particle
    domains less the foot of body 1's, along the last axis (x2 in a plane case, x3 in 3D)."""
    part = read_particles(os.path.join(case, '0', 'particles.vtp'))
    up = len(part['Points'][0]) - 1
    if up == 2 and all(abs(x[2]) < 1e-12 for x in part['Points']):
        up = 1   # a plane case written with three coordinates
    ys = [(b, x[up], s[up]) for b, x, s in zip(part['body'], part['Points'], part['halfSize'])]
    surface = max(y + s for b, y, s in ys if b == 0)
    foot = min(y - s for b, y, s in ys if b == 1)
    return surface - foot


def cell_size(case):
    """The (square) cell size of <case>/constant/grid."""
    return float(re.search(r'cellSize\s+([0-9.e-]+);', open(os.path.join(case, 'constant', 'grid')).read()).group(1))


def write_deposit(case, distances, heights):
    """<case>/deposit.dat: a (distance, height) pair per particle, for the deposit plot."""
    with open(os.path.join(case, 'deposit.dat'), 'w') as f:
        for r, y in zip(distances, heights):
            f.write('%g %g\n' % (r, y))


def deposit_front(distances, heights, cell, thin):
    """Where a deposit ends: binned by `distances` (from a wall or an axis) in cells of
    `cell`, the edge of the first bin past the one at the wall whose highest particle lies
    below `thin`."""
    height = {}
    for r, y in zip(distances, heights):
        b = int(r / cell)
        height[b] = max(height.get(b, 0.0), y)
    b = 0
    while height.get(b + 1, 0.0) >= thin:
        b += 1
    return (b + 1) * cell


def read_particles(path):
    """Point arrays of a particles.vtp (raw appended binary, UInt64 headers), by name.

    Each array is a list of tuples (one per particle) or of numbers for one component;
    positions are under 'Points'. Tensors have 9 components, row-major (xx xy xz yx yy ...).
    """
    with open(path, 'rb') as f:
        data = f.read()
    start = data.index(b'<AppendedData')
    start = data.index(b'_', start) + 1
    header = data[:start].decode('ascii', 'replace')
    piece = header[header.index('<Piece'):header.index('</Points>')]
    codes = {'Float64': 'd', 'Float32': 'f', 'Int32': 'i', 'Int64': 'q', 'UInt8': 'B'}
    arrays = {}
    for tag in re.findall(r'<DataArray[^>]*>', piece):
        attr = dict(re.findall(r'(\w+)="([^"]*)"', tag))
        code = codes[attr['type']]
        at = start + int(attr['offset'])
        nbytes = struct.unpack_from('<Q', data, at)[0]
        values = struct.unpack_from('<%d%s' % (nbytes // struct.calcsize(code), code), data, at + 8)
        n = int(attr.get('NumberOfComponents', '1'))
        arrays[attr['Name']] = list(values) if n == 1 else \
            [values[k:k + n] for k in range(0, len(values), n)]
    return arrays


def option(argv, name, count, default):
    """The `count` numbers after `name` on a command line, or `default` when it is absent."""
    if name not in argv:
        return default
    k = argv.index(name)
    return [float(v) for v in argv[k + 1:k + 1 + count]]


def read_series(case, function_object, file):
    """Columns of `file` from every postProcessing/<function_object>/<start>/ directory of a
    case, in time order. A restart adds a directory; its lines replace the earlier run's
    from its start on."""
    paths = sorted(glob.glob(os.path.join(case, 'postProcessing', function_object, '*', file)),
                   key=lambda p: float(os.path.basename(os.path.dirname(p))))
    series = {}
    for path in paths:
        c = read_columns(path)
        start = c['time'][0] if c.get('time') else float('inf')
        while series.get('time') and series['time'][-1] >= start:
            for column in series.values():
                column.pop()
        for name, values in c.items():
            series.setdefault(name, []).extend(values)
    return series


def tool_forces(case, body, face=None):
    """(time, Fx, Fy, dx) of `body` from every postProcessing/forces/<start>/forces.dat of a
    case, in time order: the force of the material on the tool (on its `face` of the forces
    function object's `faces`, if given) and the tool's travel."""
    c = read_series(case, 'forces', 'forces.dat')
    if not c:
        return [], [], [], []
    return c['time'], c[(face or body) + ':Fx'], c[(face or body) + ':Fy'], c[body + ':dx']


def window_mean(t, f, keep):
    """Trapezoidal time average of f over the consecutive samples where keep is true; None
    when no two consecutive samples are kept."""
    area = span = 0.0
    for k in range(1, len(t)):
        if keep[k - 1] and keep[k]:
            area += 0.5 * (f[k - 1] + f[k]) * (t[k] - t[k - 1])
            span += t[k] - t[k - 1]
    return area / span if span > 0 else None


def settled_window_mean(path, settlement, pressure, lo, hi):
    """The mean of the pressure samples whose settlement lies in [lo, hi] (a footing's
    collapse pressure); exits naming `path` when the push stopped short of the window."""
    import sys
    end = settlement[-1]
    window = [p for s, p in zip(settlement, pressure) if lo <= s <= hi]
    if not window or end < lo:
        sys.exit(f'{path}: the push reached {end:.1f} mm, short of the window {lo:g}..{hi:g} mm')
    return sum(window) / len(window)


def report_footing(case, path, settlement, pressure, reference, c, lo, hi, series):
    """A footing's collapse pressure from its settlement [mm] and pressure [kPa] series: prints
    q_u (the mean over lo ... hi mm), its error against `reference` [kPa] in %, q_u / c, the peak
    pressure and the settlement reached; with `series` also writes <case>/pressure.dat
    (settlement [mm], P [kPa], P / c)."""
    q_u = settled_window_mean(path, settlement, pressure, lo, hi)
    print(f'{q_u:.1f} {(q_u - reference) / reference * 100:.2f} {q_u * 1e3 / c:.3f} '
          f'{max(pressure):.1f} {settlement[-1]:.1f}')
    if series:
        rows = ['%.4f %.3f %.4f' % (s, p, p * 1e3 / c) for s, p in zip(settlement, pressure)]
        with open(os.path.join(case, 'pressure.dat'), 'w') as f:
            f.write('# settlement [mm] footing pressure P [kPa] P / c\n' + '\n'.join(rows) + '\n')
