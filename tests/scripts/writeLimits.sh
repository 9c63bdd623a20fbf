#!/bin/bash
# Write limits that used to kill the applications mid-write: under a file-size limit
# (ulimit -f, SIGXFSZ) picInit and picSolver stop with one line naming the file and the reason
# (exit 2), leave no hidden temporary directory, and picSolver keeps its last good state; a
# closed output pipe (SIGPIPE) does not stop a run, which ends with its state written.
# Usage: writeLimits.sh <source dir> <binary dir>
. "$(dirname "$0")/scratchRun.sh" "$@"
cp -r "$source_dir/tutorials/verification/twoDisks" "$work/case"
cd "$work/case"
./Allclean > /dev/null
fail() { echo "writeLimits: $*"; exit 1; }

# picInit: its particles (about 120 KiB) above a 20 KiB limit.
status=0; (ulimit -f 20; picInit > init.out 2> init.err) || status=$?
[ "$status" = 2 ] || fail "picInit under ulimit -f 20 exited $status: $(cat init.err)"
[ "$(wc -l < init.err)" = 1 ] || fail "picInit: expected one error line, got: $(cat init.err)"
grep -q "File too large" init.err || fail "picInit does not say why: $(cat init.err)"
ls -a | grep -q '\.tmp' && fail "picInit left a temporary behind: $(ls -a)"

# picSolver: the start is written, the first time directory is not.
picInit > /dev/null
sed -i 's/^endTime .*/endTime 0.2;/' system/controlDict
status=0; (ulimit -f 60; picSolver > solver.out 2> solver.err) || status=$?
[ "$status" = 2 ] || fail "picSolver under ulimit -f 60 exited $status: $(cat solver.err)"
[ "$(wc -l < solver.err)" = 1 ] || fail "picSolver: expected one error line, got: $(cat solver.err)"
grep -q "File too large" solver.err || fail "picSolver does not say why: $(cat solver.err)"
ls -a | grep -q '\.tmp' && fail "picSolver left a temporary behind: $(ls -a)"
[ -f 0/particles.vtp ] || fail "the start state is gone"

# A closed pipe: the run goes on to its end and writes its last time directory.
rm -rf 0.* postProcessing
picSolver | head -1 > /dev/null
status=${PIPESTATUS[0]}
[ "$status" = 0 ] || fail "picSolver | head -1 exited $status"
[ -f 0.2/particles.vtp ] || fail "picSolver | head -1 did not write its last state: $(ls)"
echo "writeLimits: ok"
