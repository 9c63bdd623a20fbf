"""picStudy: runs the design study of system/studyDict in a base case.

    picStudy                  write the cases, run those not yet finished, collect
    picStudy -dryRun          write the cases and list each one's changed entries; run nothing
    picStudy -maxCases N      run at most N cases now (the others on a later call)
    picStudy -executor slurm  run on Slurm instead of studyDict's executor
    picStudy -noWait          slurm: submit and return; collect later with -collect
    picStudy -collect         run nothing: gather results.csv and the plots of what has run
    picStudy -rerunFailed     run failed cases again (by default they keep their status)
    picStudy -case DIR -output DIR -parallel N

Cases go to <output>/<name>/<case>/ (output: the base case's studies/). A case holds a copy
of the base case with the study's entries rewritten and, when its run ends, its status file:
a study stopped at any point and started again runs only the cases without one.
Exit status: 0 every case run has finished, 1 bad input, 2 a case failed, 128 + n stopped
by signal n.
"""
import argparse
import collections
import os
import sys

from . import cases as casefiles
from . import executors, report, results, studydict
from .errors import InputError

# A design of more cases than this is warned: each case is a copy of the base case, written
# before any runs.
LARGE_DESIGN = 10000


class Parser(argparse.ArgumentParser):
    def error(self, message):
        print('Error: command line: %s (picStudy -help lists the options)' % message, file=sys.stderr)
        sys.exit(1)


def arguments(argv):
    p = Parser(prog='picStudy', description='Design studies of a granular-pic case (system/studyDict).',
               add_help=False, formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    p.add_argument('-help', '--help', '-h', action='help', help='show this help and exit')
    p.add_argument('-case', default='.', help='the base case (default: .)')
    p.add_argument('-output', help="the studies' directory (default: <case>/studies)")
    p.add_argument('-dryRun', action='store_true', help='write and list the cases, run nothing')
    p.add_argument('-executor', help="local or slurm instead of studyDict's executor")
    p.add_argument('-maxCases', type=int, help='run at most this many cases now')
    p.add_argument('-parallel', type=int, help='local: cases at a time')
    p.add_argument('-noWait', action='store_true', help='slurm: submit and return')
    p.add_argument('-collect', action='store_true', help='run nothing, collect what has run')
    p.add_argument('-rerunFailed', action='store_true', help='run failed cases again')
    p.add_argument('-quiet', action='store_true', help='no diffs, only the changed entries')
    args = p.parse_args(argv)
    if args.maxCases is not None and args.maxCases < 0:
        p.error("option '-maxCases': %d is below 0" % args.maxCases)
    if args.parallel is not None and args.parallel < 1:
        p.error("option '-parallel': %d is below 1" % args.parallel)
    return args


def to_run(case, study, rerun_failed):
    status = case.status()
    if not case.is_current(status, study.run):
        return True
    return rerun_failed and status['status'] == 'failed'


def describe(study, case, quiet):
    print('%s:' % case.name)
    for file, changes in case.changes.items():
        for path, value in changes.items():
            print('    %s %s: %s' % (file, path, value))
    if not quiet:
        sys.stdout.write(casefiles.diff(study, case))


def base_case_bytes(base):
    """The bytes of the base case's files that each case copies (not its output)."""
    total = 0
    for name in os.listdir(base):
        if casefiles.is_output(name):
            continue
        path = os.path.join(base, name)
        if os.path.isdir(path):
            for root, _, files in os.walk(path):
                total += sum(os.path.getsize(os.path.join(root, f)) for f in files)
        elif os.path.isfile(path):
            total += os.path.getsize(path)
    return total


def size_text(n):
    for unit in ('B', 'KiB', 'MiB', 'GiB', 'TiB'):
        if n < 1024 or unit == 'TiB':
            return '%.3g %s' % (n, unit)
        n /= 1024.0


class Progress:
    """A line every twentieth of `total` (at least every 100) where there are 200 or more,
    so that a long stretch of writing (some 10 ms a case) is seen going."""

    def __init__(self, what, total):
        self.what, self.total, self.done = what, total, 0
        self.every = max(100, total // 20) if total >= 200 else 0

    def step(self):
        self.done += 1
        if self.every and (self.done % self.every == 0 or self.done == self.total):
            print('%s: %d of %d' % (self.what, self.done, self.total), flush=True)


def summary(rows):
    counts = {}
    for row in rows:
        counts[row['status']] = counts.get(row['status'], 0) + 1
    return ', '.join('%d %s' % (n, s) for s, n in sorted(counts.items()))


def main(argv=None):
    args = arguments(sys.argv[1:] if argv is None else argv)
    try:
        return study_main(args)
    except InputError as e:
        print('Error: %s' % e, file=sys.stderr)
        return 1
    except RuntimeError as e:
        print('Error: %s' % e, file=sys.stderr)
        return 2
    except BrokenPipeError:
        # the reader of the output stopped (picStudy -dryRun | head): not an error of the study
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1


def study_main(args):
    study = studydict.read(args.case, args.executor)
    if args.parallel:
        study.local['parallel'] = args.parallel
    directory = casefiles.study_directory(study, args.output)
    count = len(study.points())
    if count > LARGE_DESIGN:   # said before the cases are made: that alone takes a while
        each = base_case_bytes(study.base)
        print('Warning: %s: the design makes %d cases (more than %d), each a copy of the base case of about '
              '%s: %s in all; -maxCases N runs them N at a time'
              % (study.dict_label, count, LARGE_DESIGN, size_text(each), size_text(each * count)),
              file=sys.stderr, flush=True)
    all_cases = casefiles.make_cases(study, args.output)
    duplicate = sorted(n for n, k in collections.Counter(c.name for c in all_cases).items() if k > 1)
    if duplicate:
        raise InputError(study.dict_label, 0, 'two cases would share the directory %s: give values that differ'
                         % duplicate[0])
    os.makedirs(directory, exist_ok=True)
    pending = [c for c in all_cases if to_run(c, study, args.rerunFailed)]
    print('Study %s: %d cases (%s design), %d to run, in %s'
          % (study.name, len(all_cases), study.design, len(pending), directory))
    lost = {}
    queued = None
    if study.executor == 'slurm' and not (args.collect or args.dryRun):
        queued = executors.queued_job(directory)
    if queued:
        # an earlier call's array still runs the cases: follow it, neither rewrite nor rerun them
        print('slurm: job array %s of an earlier call is still queued: following it' % queued)
        code = run(study, directory, executors.submitted_cases(directory, all_cases), lost, args, queued)
        if code is not None:
            return code
    elif not args.collect:
        if args.maxCases is not None:
            pending = pending[:args.maxCases]
        writing = {id(c) for c in pending}
        progress = Progress('Writing cases', len(pending))
        for case in all_cases:
            if id(case) in writing:
                casefiles.write_case(study, case)
                progress.step()
            elif not args.dryRun:
                continue
            describe(study, case, args.quiet)
        if args.dryRun:
            print('Dry run: %d cases written, nothing run' % len(pending))
            return 0
        if pending:
            code = run(study, directory, pending, lost, args)
            if code is not None:
                return code
    rows = [results.collect(study, c, lost.get(c.name)) for c in all_cases]
    path = report.write_csv(study, directory, rows)
    plots = report.plot(study, directory, rows)
    print('Results: %s (%s)' % (path, summary(rows)))
    if plots:
        print('Plots: %s/plots/*.png (%d)' % (directory, len(plots)))
    for row, case in zip(rows, all_cases):
        if row['status'] == 'failed':
            print('  %s failed: %s' % (case.name, row['error']))
    return 2 if any(r['status'] == 'failed' for r in rows) else 0


def run(study, directory, pending, lost, args, job=None):
    """Runs the pending cases (or follows the Slurm array `job` that runs them); an exit
    status when the study must stop before collecting."""
    if study.executor == 'local':
        def ended(case, code):
            row = results.collect(study, case)
            if row['status'] == 'finished':
                print('  %s finished (wall %s s)' % (case.name, row['wallTime_s']), flush=True)
            elif row['status'] == 'failed':
                print('  %s failed: %s' % (case.name, row['error']), flush=True)
            else:
                print('  %s stopped (exit %d): runs again on resume' % (case.name, code), flush=True)
        try:
            executors.run_local(pending, study.local, ended)
        except executors.Interrupted as e:
            rows = [results.collect(study, c) for c in casefiles.make_cases(study, args.output)]
            report.write_csv(study, directory, rows)
            print('Stopped by signal %d: %s; picStudy again resumes' % (e.number, summary(rows)))
            return 128 + e.number
        return None
    if job is None:
        job = executors.submit_slurm(study, directory, pending, study.slurm)
    if args.noWait:
        print('Follow it with: squeue -j %s; then collect with: picStudy -collect' % job)
        return 0
    executors.follow_slurm(job, study.slurm.get('pollInterval', 10),
                           lambda states: print('  job %s: %s' % (job, states), flush=True))
    states = None
    for index, case in enumerate(pending):
        if case is not None and not case.is_current(case.status(), study.run):
            if states is None:
                states = executors.task_end_states(job)
            how = states.get(str(index), 'see %s/slurm/%s_%d.out' % (directory, job, index))
            lost[case.name] = 'the Slurm task ended without a status (%s)' % how
    return None


if __name__ == '__main__':
    sys.exit(main())
