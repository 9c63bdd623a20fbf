"""Where the cases run. Both run each case through picstudy.runcase, so a case's files and
status are the same whichever ran it.

local: N cases at a time on this machine, each with OMP_NUM_THREADS = cores / N so that
       the cases together never ask for more threads than there are cores.
slurm: one job array (a task per case), submitted with sbatch and followed with squeue
       until its tasks have left the queue (sacct, where accounting is on, says how a task
       that wrote no status ended).
"""
import os
import shlex
import signal
import subprocess
import sys
import time

from . import runcase

PACKAGE_PARENT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def worker_command(case_directory):
    return [sys.executable, '-m', 'picstudy.runcase', case_directory]


def worker_environment(threads=None):
    env = dict(os.environ)
    env['PYTHONPATH'] = PACKAGE_PARENT + (os.pathsep + env['PYTHONPATH'] if env.get('PYTHONPATH') else '')
    if threads is not None:
        env['OMP_NUM_THREADS'] = str(threads)
    return env


def cores():
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:
        return os.cpu_count() or 1


class Interrupted(Exception):
    def __init__(self, number):
        super().__init__(number)
        self.number = number


def run_local(cases, options, report):
    """Runs the cases, `parallel` at a time; report(case, exit code) as each ends. A SIGINT
    or SIGTERM is passed on to the running cases, which stop writing their last state (and
    no status, so they run again on resume); then Interrupted is raised."""
    available = options.get('cores') or cores()
    parallel = max(1, min(options.get('parallel') or available, len(cases) or 1))
    threads = max(1, available // parallel)
    print('local: %d case%s at a time, OMP_NUM_THREADS=%d (%d cores)'
          % (parallel, '' if parallel == 1 else 's', threads, available))
    waiting, running, stopped = list(cases), {}, []

    def stop(number, frame):
        if not stopped:
            stopped.append(number)
            for process in running:
                process.send_signal(number)
    previous = {s: signal.signal(s, stop) for s in (signal.SIGINT, signal.SIGTERM)}
    try:
        while waiting or running:
            while waiting and len(running) < parallel and not stopped:
                case = waiting.pop(0)
                print('  running %s' % case.name, flush=True)
                # setsid: a terminal's Ctrl-C reaches the case only through this loop, once
                process = subprocess.Popen(worker_command(case.directory), env=worker_environment(threads),
                                           start_new_session=True, preexec_fn=runcase.die_with_parent)
                running[process] = case
            time.sleep(0.1)
            for process in [p for p in running if p.poll() is not None]:
                report(running.pop(process), process.returncode)
            if stopped and not running:
                break
    finally:
        for s, handler in previous.items():
            signal.signal(s, handler)
    if stopped:
        raise Interrupted(stopped[0])


def job_script(study, study_directory, list_path, options):
    """The job array's script: task i runs line i + 1 of the case list."""
    lines = ['#!/bin/bash',
             '#SBATCH --job-name=%s' % study.name,
             '#SBATCH --cpus-per-task=%d' % options.get('coresPerTask', 1),
             '#SBATCH --output=%s' % os.path.join(study_directory, 'slurm', '%A_%a.out')]
    if options.get('partition'):
        lines.append('#SBATCH --partition=%s' % options['partition'])
    if options.get('timeLimit'):
        lines.append('#SBATCH --time=%s' % options['timeLimit'])
    if options.get('account'):
        lines.append('#SBATCH --account=%s' % options['account'])
    for option in options.get('options', []):
        lines.append('#SBATCH %s' % option)
    lines += ['# the study %s of %s (picStudy); the environment is the submitting shell\'s' % (study.name, study.base),
              'export OMP_NUM_THREADS=${SLURM_CPUS_PER_TASK:-1}',
              'export PYTHONPATH=%s${PYTHONPATH:+:$PYTHONPATH}' % shlex.quote(PACKAGE_PARENT),
              'case=$(sed -n "$((SLURM_ARRAY_TASK_ID + 1))p" %s)' % shlex.quote(list_path),
              'exec %s -m picstudy.runcase "$case"' % shlex.quote(sys.executable), '']
    return '\n'.join(lines)


def submit_slurm(study, study_directory, cases, options):
    """Writes the case list and the job script, submits the array; returns the job id."""
    folder = os.path.join(study_directory, 'slurm')
    os.makedirs(folder, exist_ok=True)
    list_path = os.path.join(folder, 'cases')
    with open(list_path, 'w') as f:
        f.write(''.join(case.directory + '\n' for case in cases))
    script = os.path.join(folder, 'job.sh')
    with open(script, 'w') as f:
        f.write(job_script(study, study_directory, list_path, options))
    os.chmod(script, 0o755)
    command = ['sbatch', '--parsable', '--array=0-%d' % (len(cases) - 1), script]
    try:
        done = subprocess.run(command, capture_output=True, text=True)
    except OSError:
        raise RuntimeError('sbatch not found: run picStudy with the Slurm commands on PATH') from None
    if done.returncode != 0:
        raise RuntimeError('sbatch failed: ' + (done.stderr.strip().splitlines() or ['exit %d' % done.returncode])[-1])
    job = done.stdout.strip().split(';')[0]
    with open(os.path.join(folder, 'job'), 'w') as f:
        f.write(job + '\n')
    print('slurm: job array %s, %d task%s (%s)' % (job, len(cases), '' if len(cases) == 1 else 's', script))
    return job


def queued_tasks(job):
    """{array index: state} of the job's tasks still in the queue."""
    done = subprocess.run(['squeue', '-h', '-r', '-j', job, '-o', '%K %T'], capture_output=True, text=True)
    if done.returncode != 0:
        if 'Invalid job id' in done.stderr:
            return {}   # the controller has forgotten the finished job
        raise RuntimeError('squeue failed: ' + done.stderr.strip())
    tasks = {}
    for line in done.stdout.splitlines():
        words = line.split()
        if len(words) == 2:
            tasks[words[0]] = words[1]
    return tasks


def queued_job(study_directory):
    """The job id of the study's last array while any of its tasks is queued or running."""
    try:
        with open(os.path.join(study_directory, 'slurm', 'job')) as f:
            job = f.read().strip()
    except OSError:
        return None
    try:
        return job if job and queued_tasks(job) else None
    except (OSError, RuntimeError):
        return None


def submitted_cases(study_directory, cases):
    """The cases in the order of the last array's task indices."""
    by_directory = {case.directory: case for case in cases}
    with open(os.path.join(study_directory, 'slurm', 'cases')) as f:
        return [by_directory.get(line.strip()) for line in f if line.strip()]


def follow_slurm(job, interval, report_states):
    """Waits until no task of the job is queued or running, printing each change of counts."""
    last = None
    while True:
        tasks = queued_tasks(job)
        counts = {}
        for state in tasks.values():
            counts[state] = counts.get(state, 0) + 1
        summary = ', '.join('%d %s' % (n, s.lower()) for s, n in sorted(counts.items()))
        if summary != last and summary:
            report_states(summary)
            last = summary
        if not tasks:
            return
        time.sleep(interval)


def task_end_states(job):
    """{array index: 'STATE exit'} from sacct, or {} where accounting is off."""
    try:
        done = subprocess.run(['sacct', '-n', '-P', '-X', '-j', job, '-o', 'JobID,State,ExitCode'],
                              capture_output=True, text=True)
    except OSError:
        return {}
    states = {}
    if done.returncode == 0:
        for line in done.stdout.splitlines():
            words = line.split('|')
            if len(words) == 3 and '_' in words[0]:
                states[words[0].split('_')[1]] = '%s, exit %s' % (words[1], words[2])
    return states
