"""What a case yields for the study's table: each result of studyDict's `results` (a
function object's column reduced to a number), particles, steps and wall time from
log.picSolver's End: line, and the status with the error line of a failed run."""
import glob
import os

import gpicdat

from .errors import choices

FIXED_COLUMNS = ['particles', 'steps', 'wallTime_s', 'status', 'error']


def series(case_directory, result):
    """The function object's columns over every start time of the case."""
    file = result.file
    if file is None:
        found = sorted({os.path.basename(p) for p in glob.glob(os.path.join(
            case_directory, 'postProcessing', result.function_object, '*', '*.dat'))})
        file = result.function_object + '.dat' if result.function_object + '.dat' in found or not found \
            else found[0]
    return gpicdat.read_series(case_directory, result.function_object, file)


def reduce(columns, result):
    """The result's number from the columns (None where its window holds no sample)."""
    d = result.dict
    for keyword, name in (('column', result.column), ('over', result.over or 'time')):
        if name not in columns:
            d.fail(keyword, "'%s' is not a column of postProcessing/%s; valid choices: %s"
                   % (name, result.function_object, choices(list(columns))))
    t, f = columns['time'], [result.scale * v for v in columns[result.column]]
    x = columns[result.over or 'time']
    if not t:
        return None
    if result.statistic == 'last':
        return f[-1]
    if result.statistic == 'at':
        return interpolate(x, f, result.at)
    low, high = result.window
    tolerance = 1e-9 * max(1.0, abs(low) if low != float('-inf') else 1.0, abs(high) if high != float('inf') else 1.0)
    keep = [low - tolerance <= v <= high + tolerance for v in x]
    if result.statistic == 'mean':
        return gpicdat.window_mean(t, f, keep)
    kept = [v for v, k in zip(f, keep) if k]
    if not kept:
        return None
    return max(kept) if result.statistic == 'max' else min(kept)


def interpolate(x, f, at):
    """f at x = at, linear between the samples either side (x increasing); None outside."""
    for k in range(1, len(x)):
        if x[k - 1] <= at <= x[k]:
            if x[k] == x[k - 1]:
                return f[k]
            w = (at - x[k - 1]) / (x[k] - x[k - 1])
            return f[k - 1] + w * (f[k] - f[k - 1])
    return f[0] if len(x) == 1 and x[0] == at else None


def collect(study, case, lost=None):
    """{column: value} of the case's row; '' where there is nothing to say."""
    row = {'case': case.name}
    row.update({p.name: case.point[p.name] for p in study.parameters})
    row.update({r.name: '' for r in study.results})
    row.update(particles='', steps='', wallTime_s='', status='pending', error='')
    status = case.status()
    if status is None or not case.is_current(status, study.run):
        if lost:
            row.update(status='failed', error=lost)
        return row
    row.update(status=status['status'], error=status.get('error', ''))
    log = os.path.join(case.directory, 'log.picSolver')
    try:
        row['particles'], row['steps'], row['wallTime_s'] = gpicdat.run_summary(log)
    except (OSError, RuntimeError):
        row['wallTime_s'] = status.get('elapsed', '')
    if status['status'] == 'finished':
        for result in study.results:
            try:
                value = reduce(series(case.directory, result), result)
            except (OSError, KeyError, ValueError):
                value = None
            row[result.name] = '' if value is None else value
    return row

