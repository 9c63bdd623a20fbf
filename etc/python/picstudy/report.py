"""results.csv (one row per case: parameters, results, run, status) and a PNG of each result
against each parameter, one line per combination of the other parameters."""
import csv
import io
import os
import subprocess

from .results import FIXED_COLUMNS

MAX_SERIES = 8   # more lines than this make a plot unreadable: plot the points without grouping


def columns(study):
    return ['case'] + [p.name for p in study.parameters] + [r.name for r in study.results] + FIXED_COLUMNS


def cell(value):
    if isinstance(value, float):
        return '%.10g' % value
    return '' if value is None else str(value)


def write_csv(study, directory, rows):
    """results.csv, replaced whole so a reader never sees half a table."""
    names = columns(study)
    text = io.StringIO()
    writer = csv.writer(text, lineterminator='\n')
    writer.writerow(names)
    for row in rows:
        writer.writerow([cell(row.get(name)) for name in names])
    path = os.path.join(directory, 'results.csv')
    with open(path + '.tmp', 'w') as f:
        f.write(text.getvalue())
    os.replace(path + '.tmp', path)
    return path


def is_number(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def plot(study, directory, rows):
    """plots/<result>-<parameter>.png for every numeric result and parameter; the data of
    each beside it (.dat). Returns the PNGs drawn."""
    folder = os.path.join(directory, 'plots')
    os.makedirs(folder, exist_ok=True)
    drawn = []
    finished = [r for r in rows if r['status'] == 'finished']
    quantities = [(r.name, r.name) for r in study.results] + [('wallTime_s', 'wall time [s]')]
    for quantity, label in quantities:
        for p in study.parameters:
            points = [r for r in finished if is_number(r[p.name]) and is_number(r[quantity])]
            if not points:
                continue
            others = [q.name for q in study.parameters if q is not p]
            groups = {}
            for r in points:
                groups.setdefault(tuple(r[o] for o in others), []).append(r)
            if len(groups) > MAX_SERIES or study.design == 'latinHypercube':
                groups = {(): points}
            base = os.path.join(folder, '%s-%s' % (quantity, p.name))
            with open(base + '.dat', 'w') as f:
                f.write('# %s %s, one block per %s\n' % (p.name, quantity, ' '.join(others) or 'study'))
                titles = []
                for key, members in groups.items():
                    titles.append(' '.join('%s %s' % (o, cell(v)) for o, v in zip(others, key)) if key else quantity)
                    for r in sorted(members, key=lambda r: r[p.name]):
                        f.write('%s %s\n' % (cell(r[p.name]), cell(r[quantity])))
                    f.write('\n\n')
            script = '\n'.join([
                "set terminal pngcairo size 800,560 noenhanced",
                "set output '%s.png'" % base,
                "set title 'study %s: %s against %s'" % (study.name, label, p.name),
                "set xlabel '%s'" % p.name,
                "set ylabel '%s'" % label,
                "set key top left",
                "set grid",
                "plot " + ', '.join("'%s.dat' index %d using 1:2 with linespoints pt 7 title '%s'"
                                    % (base, k, t.replace("'", "''")) for k, t in enumerate(titles)),
                ''])
            try:
                subprocess.run(['gnuplot'], input=script, text=True, check=True,
                               stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
                drawn.append(base + '.png')
            except (OSError, subprocess.CalledProcessError):
                print('Warning: gnuplot did not draw %s.png (is gnuplot installed?); %s.dat has the data'
                      % (base, base))
    return drawn
