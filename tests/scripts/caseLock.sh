#!/bin/bash
# One writer per case (libpic/core/CaseLock.H): while picSolver runs a case, a second
# picSolver, picInit -overwrite and picListTimes -rm / -rebuild are refused in one line naming
# the running process, and the run goes on undisturbed; SIGTERM ends it with the lock file
# removed; after a SIGKILL the stale lock file is taken over with a warning.
# Usage: caseLock.sh <source dir> <binary dir>
. "$(dirname "$0")/scratchRun.sh" "$@"
cp -r "$source_dir/tutorials/verification/twoDisks" "$work/case"
cd "$work/case"
./Allclean > /dev/null
fail() { echo "caseLock: $*"; exit 1; }
export OMP_NUM_THREADS=1

# A run far longer than the test (1e-5 s steps to 3 s), into its first written time.
sed -i 's/^deltaT .*/deltaT 1e-5;/; s/^endTime .*/endTime 3;/' system/controlDict
picInit > /dev/null
picSolver > solver.out 2> solver.err &
pid=$!
for _ in $(seq 1 600); do [ -f 0.1/uniform/time ] && break; sleep 0.1; done
[ -f 0.1/uniform/time ] || fail "the run never wrote 0.1: $(cat solver.err)"
[ -f .picLock ] || fail "no lock file while the run goes: $(ls -a)"
grep -q "picSolver, process $pid on host " .picLock || fail "the lock file does not name the run: $(cat .picLock)"

refused() {  # <what> <command...>: exit 1, one line naming the lock file and the run
    local what=$1; shift
    local status=0
    "$@" > refused.out 2> refused.err || status=$?
    [ "$status" = 1 ] || fail "$what on a running case exited $status: $(cat refused.err)"
    [ "$(wc -l < refused.err)" = 1 ] || fail "$what: expected one error line, got: $(cat refused.err)"
    grep -q "^Error: .*\.picLock: the case is in use by picSolver, process $pid on host " refused.err ||
        fail "$what does not name the run: $(cat refused.err)"
}
refused "a second picSolver" picSolver
refused "picInit -overwrite" picInit -overwrite
refused "picListTimes -rm" picListTimes -rm
refused "picListTimes -rebuild" picListTimes -rebuild
[ -f 0.1/particles.vtp ] || fail "a refused command changed the case: $(ls)"
picListTimes > /dev/null || fail "listing the times of a running case is refused"
kill -0 "$pid" 2> /dev/null || fail "the run did not survive the refusals: $(cat solver.err)"

# SIGTERM: the run stops cleanly and gives the case back.
kill -TERM "$pid"
status=0; wait "$pid" || status=$?
[ "$status" = 143 ] || fail "SIGTERM: picSolver exited $status: $(cat solver.err)"
[ -e .picLock ] && fail "the lock file outlived the run stopped by SIGTERM"

# SIGKILL leaves the lock file behind, with no process holding it: taken over with a warning.
picSolver > solver.out 2> solver.err &
pid=$!
for _ in $(seq 1 600); do grep -q "process $pid" .picLock 2> /dev/null && break; sleep 0.05; done
grep -q "process $pid" .picLock || fail "the second run did not lock the case"
kill -KILL "$pid"
wait "$pid" || true
[ -f .picLock ] || fail "no lock file left by the killed run"
latest=$(picListTimes | tail -1)
sed -i "s/^endTime .*/endTime $(awk "BEGIN { print $latest + 0.001 }");/" system/controlDict
picSolver > solver.out 2> solver.err || fail "a run after a killed one failed: $(cat solver.err)"
grep -q "^Warning: .*\.picLock: taking over the stale lock of picSolver, process $pid on host .*: that process is gone" \
    solver.err || fail "no warning on the stale lock: $(cat solver.err)"
[ -e .picLock ] && fail "the lock file outlived the run"
echo "caseLock: ok"
