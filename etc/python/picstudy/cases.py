"""The cases of a study: copies of the base case with only the parameters' entries rewritten,
each beside a status file that says whether it has run."""
import difflib
import json
import os
import shutil

from . import foamdict

STATUS_FILE = 'studyStatus'   # written when the case's run ends, finished or failed
RUN_FILE = 'studyRun'         # the commands and entries of the case, for its run


class Case:
    def __init__(self, name, directory, point, changes):
        self.name, self.directory, self.point, self.changes = name, directory, point, changes

    def status(self):
        """The status file's content ({'status': 'finished' | 'failed', ...}) or None."""
        try:
            with open(os.path.join(self.directory, STATUS_FILE)) as f:
                return json.load(f)
        except (OSError, ValueError):
            return None

    def is_current(self, status, run):
        """Whether a status belongs to this case's entries and commands (a changed studyDict
        makes a finished case stale, and it runs again)."""
        return status is not None and status.get('entries') == self.changes and status.get('run') == run


def study_directory(study, output=None):
    return os.path.join(os.path.abspath(output) if output else os.path.join(study.base, 'studies'), study.name)


def make_cases(study, output=None):
    directory = study_directory(study, output)
    points = study.points()
    return [Case(name, os.path.join(directory, name), point, study.entry_values(point))
            for name, point in zip(study.case_names(points), points)]


def is_output(name):
    """What a run of the base case leaves: time directories, logs, postProcessing, studies."""
    try:
        float(name)
        return True
    except ValueError:
        pass
    return name in ('studies', 'postProcessing') or name.startswith(('log.', '.')) \
        or name.endswith(('.pvd', '.tmp'))


def rewritten(study, case):
    """{file: (base text, case text)} of the files the case changes."""
    out = {}
    for file, changes in case.changes.items():
        text = foamdict.read_text(os.path.join(study.base, file), file)
        out[file] = (text, foamdict.replace_values(text, file, changes))
    return out


def write_case(study, case):
    """The case directory afresh: the base case's files (not its output) with the entries
    rewritten in place. Built beside and renamed, so a case is never half written."""
    building = case.directory + '.building'
    shutil.rmtree(building, ignore_errors=True)
    os.makedirs(building)
    skip = os.path.realpath(os.path.dirname(case.directory))
    for name in sorted(os.listdir(study.base)):
        source = os.path.join(study.base, name)
        if is_output(name) or os.path.realpath(source) == skip:
            continue
        if os.path.isdir(source):
            shutil.copytree(source, os.path.join(building, name), symlinks=True,
                            ignore=shutil.ignore_patterns('studyDict'))
        else:
            shutil.copy2(source, os.path.join(building, name))
    for file, (_, text) in rewritten(study, case).items():
        with open(os.path.join(building, file), 'w', encoding='utf-8') as f:
            f.write(text)
    with open(os.path.join(building, RUN_FILE), 'w') as f:
        json.dump({'run': study.run, 'entries': case.changes}, f, indent=1)
    shutil.rmtree(case.directory, ignore_errors=True)
    os.replace(building, case.directory)


def diff(study, case):
    """The unified diff of the case's files against the base case's."""
    lines = []
    for file, (base, text) in rewritten(study, case).items():
        lines += difflib.unified_diff(base.splitlines(True), text.splitlines(True),
                                      'base/' + file, case.name + '/' + file, n=0)
    return ''.join(line if line.endswith('\n') else line + '\n' for line in lines)
