#!/bin/bash
# Allocations beyond what the process may have (ulimit -v) name what they were for and how
# much they needed, in one line with the file, line and keyword, instead of a bare
# std::bad_alloc: the grid's node arrays (a grid within the machine's memory but beyond the
# limit) and the particle arrays (a body of too many particles).
# Usage: memoryLimits.sh <source dir> <binary dir>
. "$(dirname "$0")/scratchRun.sh" "$@"
cp -r "$source_dir/tutorials/verification/twoDisks" "$work/case"
cd "$work/case"
./Allclean > /dev/null
fail() { echo "memoryLimits: $*"; exit 1; }
export OMP_NUM_THREADS=1
limit=1000000   # KiB of address space: about 1 GiB, well above what twoDisks takes

status=0; (ulimit -v $limit; picInit > init.out 2> init.err) || status=$?
[ "$status" = 0 ] || fail "twoDisks itself does not fit under ulimit -v $limit: $(cat init.err)"
rm -rf 0

# 4000 x 4000 cells: 16 million nodes, some 1.4 GiB of node arrays.
cp constant/grid grid.good
sed -i 's/^nCells .*/nCells (4000 4000);/; s/^cellSize .*/cellSize 0.0005;/' constant/grid
status=0; (ulimit -v $limit; picInit > init.out 2> init.err) || status=$?
[ "$status" = 1 ] || fail "picInit on a grid beyond ulimit -v exited $status: $(cat init.err)"
[ "$(wc -l < init.err)" = 1 ] || fail "picInit: expected one error line, got: $(cat init.err)"
grep -q "^Error: constant/grid:[0-9]*: nCells: out of memory: the grid's node arrays (16008001 nodes) need 1.[0-9]* GiB" init.err ||
    fail "the grid's allocation is not named: $(cat init.err)"
cp grid.good constant/grid

# 10 x 10 particles in each cell of both disks, on cells 20 times smaller: some 6 million
# particles, more than the limit holds.
sed -i "s/^nCells .*/nCells (500 500);/; s/^cellSize .*/cellSize 0.002;/" constant/grid
sed -i 's/particlesPerCell *[0-9]*;/particlesPerCell 10;/' constant/bodies
status=0; (ulimit -v $limit; picInit > init.out 2> init.err) || status=$?
[ "$status" = 1 ] || fail "picInit on bodies beyond ulimit -v exited $status: $(cat init.err)"
[ "$(wc -l < init.err)" = 1 ] || fail "picInit: expected one error line, got: $(cat init.err)"
grep -q "^Error: constant/bodies:[0-9]*: body '[a-zA-Z]*', particlesPerCell 10: out of memory: the particle arrays of [0-9]* particles need " init.err ||
    fail "the particles' allocation is not named: $(cat init.err)"
ls -a | grep -q '\.tmp' && fail "a temporary was left behind: $(ls -a)"
[ -e 0 ] && fail "a time directory was written"
echo "memoryLimits: ok"
