"""One case's run, the same on this machine and in a Slurm task:

    python3 -m picstudy.runcase <case directory>

runs the study's commands in the case (each logged to log.<application>), then writes the
case's status file, atomically, as the last thing it does: a case without one has not
run to its end and runs again when the study resumes. A run stopped by a signal (Ctrl-C,
a batch system's kill) writes none, so it counts as not run.
"""
import ctypes
import json
import os
import shlex
import signal
import socket
import subprocess
import sys
import time

from .cases import RUN_FILE, STATUS_FILE


def last_line(path):
    """The last non-empty line of a log: the project's errors are one line at the end."""
    try:
        with open(path, errors='replace') as f:
            lines = [line.strip() for line in f if line.strip()]
        return lines[-1] if lines else ''
    except OSError:
        return ''


def write_atomically(path, text):
    temporary = path + '.tmp'
    with open(temporary, 'w') as f:
        f.write(text)
        f.flush()
        os.fsync(f.fileno())
    os.replace(temporary, path)


def die_with_parent():
    """For Popen's preexec_fn: the child gets SIGTERM when the process that started it dies,
    so a study killed outright (a test's time-out, kill -9) leaves no run behind, though
    each run is started with setsid (below)."""
    try:
        ctypes.CDLL(None, use_errno=True).prctl(1, signal.SIGTERM)   # PR_SET_PDEATHSIG
    except (OSError, AttributeError):
        pass


class Stop:
    """The first SIGINT or SIGTERM, passed on once to the running command. The command runs
    with setsid, so a terminal's Ctrl-C reaches it only this way: twice would
    end picSolver at once instead of letting it write its last state."""

    def __init__(self):
        self.signal, self.child = None, None
        signal.signal(signal.SIGINT, self.received)
        signal.signal(signal.SIGTERM, self.received)

    def received(self, number, frame):
        if self.signal is None:
            self.signal = number
            if self.child is not None and self.child.poll() is None:
                self.child.send_signal(number)


def run(case_directory):
    with open(os.path.join(case_directory, RUN_FILE)) as f:
        plan = json.load(f)
    stop = Stop()
    started = time.time()
    status = {'status': 'finished', 'error': '', 'exitCode': 0, 'host': socket.gethostname(),
              'entries': plan['entries'], 'run': plan['run']}
    for command in plan['run']:
        words = shlex.split(command)
        log = 'log.' + os.path.basename(words[0]) if words else 'log.run'
        with open(os.path.join(case_directory, log), 'w') as out:
            stop.child = subprocess.Popen(['bash', '-c', command], cwd=case_directory, stdout=out,
                                          stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                          start_new_session=True, preexec_fn=die_with_parent)
            code = stop.child.wait()
        if stop.signal is not None or code < 0 or code >= 128:
            return 128 + (stop.signal or (-code if code < 0 else code - 128))   # no status: runs again
        if code != 0:
            status.update(status='failed', exitCode=code, command=command,
                          error=last_line(os.path.join(case_directory, log)) or '%s exited with %d' % (command, code))
            break
    status['elapsed'] = round(time.time() - started, 3)
    write_atomically(os.path.join(case_directory, STATUS_FILE), json.dumps(status, indent=1) + '\n')
    return 0


if __name__ == '__main__':
    if len(sys.argv) != 2:
        sys.exit('usage: python3 -m picstudy.runcase <case directory>')
    sys.exit(run(sys.argv[1]))
