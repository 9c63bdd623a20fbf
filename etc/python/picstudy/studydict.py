"""system/studyDict read into a Study, every input checked against the base case before
anything is written: a bad entry is one error naming the file, line and keyword."""
import os
import re

from . import design, expression, foamdict
from .errors import InputError, choices

DESIGNS = ['factorial', 'latinHypercube']
EXECUTORS = ['local', 'slurm']
STATISTICS = ['mean', 'max', 'min', 'at', 'last']
DEFAULT_RUN = ['picInit', 'picSolver']
STUDY_DICT = 'system/studyDict'


class Target:
    """One entry of a case file that a parameter sets: its text is `template` with each
    {expression} evaluated (the bare parameter when no template is given)."""

    def __init__(self, file, entry, template, line, where):
        self.file, self.entry, self.template, self.line = file, entry, template, line
        self.where = where   # the studyDict dictionary that gives it, for errors


class Parameter:
    def __init__(self, name, values, bounds, targets, line):
        self.name, self.values, self.targets, self.line = name, values, targets, line
        self.bounds = bounds    # (start, end) of a range, what a Latin hypercube samples


class Result:
    """A column of a function object's .dat files, reduced to one number per case."""

    def __init__(self, name, function_object, file, column, scale, statistic, over, window, at, dict_):
        self.name, self.function_object, self.file, self.column = name, function_object, file, column
        self.scale, self.statistic, self.over, self.window, self.at = scale, statistic, over, window, at
        self.dict = dict_   # for errors found when the files are read


class Study:
    def __init__(self):
        self.base = self.name = self.design = None
        self.parameters, self.results, self.run = [], [], list(DEFAULT_RUN)
        self.executor, self.local, self.slurm = 'local', {}, {}
        self.samples = self.seed = None

    def points(self):
        """The parameter values of every case, in case order."""
        if self.design == 'latinHypercube':
            return design.latin_hypercube(self.parameters, self.samples, self.seed)
        return design.factorial(self.parameters)

    def case_names(self, points):
        if self.design == 'latinHypercube':
            width = max(3, len(str(len(points) - 1)))
            return ['sample%0*d' % (width, k) for k in range(len(points))]
        return ['_'.join(p.name + re.sub(r'[^\w.+-]', '_', expression.format_value(point[p.name]))
                         for p in self.parameters) for point in points]

    def entry_values(self, point):
        """{file: {keyword path: text}} that the case at `point` writes."""
        changes = {}
        for p in self.parameters:
            for t in p.targets:
                if t.template is None:
                    text = expression.format_value(point[p.name])
                else:
                    try:
                        text = expression.fill(t.template, point)
                    except expression.ExpressionError as e:
                        raise InputError(self.dict_label, t.line, "keyword 'value' in dictionary %s: %s"
                                         % (t.where, e)) from None
                changes.setdefault(t.file, {})[t.entry] = text
        return changes


def read(base, executor_override=None):
    """The Study of the case directory `base` (its system/studyDict)."""
    path = os.path.join(base, STUDY_DICT)
    if not os.path.isfile(path):
        raise InputError(STUDY_DICT, 0, 'no such file in case %s' % base)
    top = foamdict.read(path, STUDY_DICT)
    study = Study()
    study.base = os.path.abspath(base)
    study.dict_label = STUDY_DICT
    study.name = top.optional('name', os.path.basename(study.base))
    if not isinstance(study.name, str) or not re.fullmatch(r'[\w.+-]+', study.name):
        top.fail('name', "'%s' is not a directory name (letters, digits, . _ + -)" % (study.name,))
    study.design = top.get_word('design', DESIGNS, 'factorial')
    if study.design == 'latinHypercube':
        study.samples = top.get_number('samples', condition=lambda n: isinstance(n, int) and n >= 1,
                                       text='a whole number of at least 1')
        study.seed = top.get_number('seed', 0, required=False,
                                    condition=lambda n: isinstance(n, int), text='a whole number')
    study.parameters = _parameters(top.sub('parameters'), study)
    study.results = _results(top.sub('results', required=False), study)
    run = top.optional('run', DEFAULT_RUN)
    if isinstance(run, str):
        run = [run]
    if not run or not all(isinstance(c, str) and c.strip() for c in run):
        top.fail('run', 'a list of commands, e.g. ("picInit" "picSolver")')
    study.run = run
    study.executor = executor_override or top.get_word('executor', EXECUTORS, 'local')
    if study.executor not in EXECUTORS:
        raise InputError('command line', 0, "option '-executor': '%s' is not a valid choice; valid choices: %s"
                         % (study.executor, choices(EXECUTORS)))
    study.local = _local(top.sub('local', required=False))
    study.slurm = _slurm(top.sub('slurm', required=False))
    study.points()   # a design that cannot be built fails here, before any case is written
    for point in study.points()[:1]:
        study.entry_values(point)
    return study


def _parameters(parameters, study):
    out = []
    for entry in parameters.entries:
        if not entry.is_dict():
            parameters.fail(entry.keyword, 'a parameter is a sub-dictionary { values (...); file ...; entry ...; }')
        if not re.fullmatch(r'[A-Za-z_]\w*', entry.keyword):
            parameters.fail(entry.keyword, 'a parameter name is a word (letters, digits, _) that expressions can use')
        d = entry.dict
        values, bounds = _values(d)
        targets = []
        if d.find('file') or d.find('entry'):
            targets.append(_target(d, study))
        sets = d.sub('set', required=False)
        for t in (sets.entries if sets else []):
            if not t.is_dict():
                sets.fail(t.keyword, 'each entry a parameter sets is a sub-dictionary { file ...; entry ...; value ...; }')
            targets.append(_target(t.dict, study))
        if not targets:
            raise InputError(d.path, d.line, "parameter '%s' sets no entry: give file and entry, or set { ... }"
                             % entry.keyword)
        for t in targets:
            other = next((p.name for p in out for u in p.targets if (u.file, u.entry) == (t.file, t.entry)), None)
            if other or sum((u.file, u.entry) == (t.file, t.entry) for u in targets) > 1:
                raise InputError(STUDY_DICT, t.line, "keyword 'entry' in dictionary %s: %s %s is set twice (also by %s)"
                                 % (t.where, t.file, t.entry, other or entry.keyword))
        out.append(Parameter(entry.keyword, values, bounds, targets, entry.line))
    if not out:
        raise InputError(parameters.path, parameters.line, 'dictionary parameters holds no parameter')
    return out


def _values(d):
    """(values, (start, end) or None) from `values (...)` or `range { ... }`."""
    if d.find('values') and d.find('range'):
        d.fail('range', 'give values or range, not both')
    if d.find('values'):
        values = d.get('values')
        if not isinstance(values, list) or not values:
            d.fail('values', 'a non-empty list in parentheses, e.g. (0.1 0.2 0.3)')
        return values, None
    r = d.sub('range', required=False)
    if r is None:
        raise InputError(d.path, d.line, "keyword 'values' is undefined in dictionary %s; valid choices: values, range"
                         % d.name)
    start, end = r.get_number('start'), r.get_number('end')
    if r.find('count') and r.find('step'):
        r.fail('step', 'give count or step, not both')
    if r.find('count'):
        count = r.get_number('count', condition=lambda n: isinstance(n, int) and n >= 1,
                             text='a whole number of at least 1')
        if count == 1 and start != end:
            r.fail('count', '1 value cannot span %g ... %g; give count 2 or more' % (start, end))
        return design.range_values(start, end, count=count), (start, end)
    if not r.find('step'):
        raise InputError(r.path, r.line, "keyword 'count' is undefined in dictionary %s; valid choices: count, step"
                         % r.name)
    step = r.get_number('step', condition=lambda s: s != 0, text='a step other than 0')
    if (end - start) * step < 0:
        r.fail('step', '%g never reaches end %g from start %g' % (step, end, start))
    return design.range_values(start, end, step=step), (start, end)


def _target(d, study):
    file = d.get('file')
    if not isinstance(file, str) or os.path.isabs(file) or '..' in file.split('/') \
            or not os.path.isfile(os.path.join(study.base, file)):
        d.fail('file', "'%s' is not a file of the base case; valid choices: %s"
               % (file, choices(_case_files(study.base))))
    keyword_path = d.get('entry')
    if not isinstance(keyword_path, str):
        d.fail('entry', 'a keyword path such as blade/velocity')
    target_dict = foamdict.read(os.path.join(study.base, file), file)
    found = target_dict.lookup(keyword_path)
    if found is None or found.is_dict():
        what = 'is a sub-dictionary of' if found else 'is not an entry of'
        d.fail('entry', "'%s' %s %s; valid choices: %s"
               % (keyword_path, what, file, choices(foamdict.value_paths(target_dict))))
    value = d.find('value')
    template = value.source() if value is not None and not value.is_dict() else None
    if value is not None and (value.is_dict() or not template.strip()):
        d.fail('value', 'the text the entry gets, e.g. "(0.3 {0.4 - depth})"')
    line = value.line if value is not None else d.find('entry').line
    return Target(file, keyword_path, template, line, d.name)


def _case_files(base):
    """The dictionaries of the base case a parameter may set (system/, constant/)."""
    out = []
    for sub in ('system', 'constant'):
        folder = os.path.join(base, sub)
        if os.path.isdir(folder):
            out += sorted(sub + '/' + f for f in os.listdir(folder)
                          if os.path.isfile(os.path.join(folder, f)) and f != 'studyDict')
    return out


def _results(d, study):
    out = []
    if d is None:
        return out
    controlDict = foamdict.read(os.path.join(study.base, 'system/controlDict'), 'system/controlDict')
    functions = controlDict.lookup('functions')
    names = functions.dict.keywords() if functions and functions.is_dict() else []
    for entry in d.entries:
        if not entry.is_dict():
            d.fail(entry.keyword, 'a result is a sub-dictionary { functionObject ...; column ...; statistic ...; }')
        r = entry.dict
        fo = r.get('functionObject')
        if fo not in names:
            r.fail('functionObject', "'%s' is not a function object of system/controlDict; valid choices: %s"
                   % (fo, choices(names)))
        statistic = r.get_word('statistic', STATISTICS, 'last')
        window = at = None
        if statistic in ('mean', 'max', 'min'):
            window = (r.get_number('from', float('-inf'), required=False),
                      r.get_number('to', float('inf'), required=False))
            if window[1] <= window[0]:
                r.fail('to', '%g is not above from %g' % (window[1], window[0]))
        elif statistic == 'at':
            at = r.get_number('time')
        out.append(Result(entry.keyword, fo, r.optional('file'), str(r.get('column')),
                          r.get_number('scale', 1, required=False), statistic,
                          r.optional('over'), window, at, r))
    return out


def _local(d):
    if d is None:
        return {}
    out = {}
    if d.find('parallel'):
        out['parallel'] = d.get_number('parallel', condition=lambda n: isinstance(n, int) and n >= 1,
                                       text='a whole number of at least 1')
    if d.find('cores'):
        out['cores'] = d.get_number('cores', condition=lambda n: isinstance(n, int) and n >= 1,
                                    text='a whole number of at least 1')
    return out


def _slurm(d):
    if d is None:
        return {}
    out = {}
    for keyword in ('partition', 'timeLimit', 'account'):
        if d.find(keyword):
            out[keyword] = str(d.get(keyword))
    if d.find('coresPerTask'):
        out['coresPerTask'] = d.get_number('coresPerTask', condition=lambda n: isinstance(n, int) and n >= 1,
                                           text='a whole number of at least 1')
    if d.find('pollInterval'):
        out['pollInterval'] = d.get_number('pollInterval', condition=lambda n: n > 0, text='seconds above 0')
    if d.find('options'):
        options = d.get('options')
        out['options'] = options if isinstance(options, list) else [options]
    return out
