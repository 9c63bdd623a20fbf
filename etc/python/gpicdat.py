"""Reading granular-pic output for tutorial scripts (standard library only)."""
import re


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


def run_summary(log_path):
    """(particles, steps, wall seconds) from the 'End:' line of a picSolver log."""
    with open(log_path) as f:
        for line in f:
            m = re.match(r'End: t = \S+, (\d+) steps, (\d+) particles, wall (\S+) s', line)
            if m:
                return int(m.group(2)), int(m.group(1)), float(m.group(3))
    raise RuntimeError('no End: line in ' + log_path + ' (did the run fail?)')
