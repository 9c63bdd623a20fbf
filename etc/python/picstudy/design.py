"""A parameter's values (a list or a range) and the designs that combine them into cases:
every combination (full factorial) or a Latin hypercube of N samples."""
import itertools
import math
import random


def range_values(start, end, count=None, step=None):
    """start ... end (both included) in `count` values or by `step`, to 12 digits so that
    steps of 0.05 give 0.15 and not 0.15000000000000002."""
    if count is not None:
        if count == 1:
            return [start]
        return [round(start + (end - start) * k / (count - 1), 12) for k in range(count)]
    # the last value may fall short of end; 1e-9 keeps a step that divides the span exactly
    n = int(math.floor((end - start) / step + 1e-9))
    return [round(start + k * step, 12) for k in range(n + 1)]


def factorial(parameters):
    """Every combination of the parameters' values, the first parameter slowest."""
    names = [p.name for p in parameters]
    return [dict(zip(names, combination))
            for combination in itertools.product(*[p.values for p in parameters])]


def latin_hypercube(parameters, samples, seed):
    """`samples` points: each parameter's span split into as many equal strata, one point in
    each, the strata paired at random. A range is sampled within its stratum; a list of
    values gives the value whose share of the list the stratum falls in. The same seed
    gives the same points."""
    rng = random.Random(seed)
    columns = {}
    for p in parameters:
        strata = list(range(samples))
        rng.shuffle(strata)
        column = []
        for s in strata:
            u = (s + rng.random()) / samples
            if p.bounds is not None:
                low, high = p.bounds
                column.append(round(low + u * (high - low), 12))
            else:
                column.append(p.values[min(int(u * len(p.values)), len(p.values) - 1)])
        columns[p.name] = column
    return [{name: columns[name][k] for name in columns} for k in range(samples)]
