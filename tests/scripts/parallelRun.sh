#!/bin/bash
# picSolver -parallel under mpirun against the serial run (doc/parallel.md): a plane column
# of sand on 2 ranks (hierarchical), a 3D cylinder of sand on 4 (scotch) and its axisymmetric
# twin on 2 (scotch), each collapsing; a rigid footing on 2 ranks and the blade with contact
# on 3, pushed into soil
# for some hundred steps with particles moving between the ranks; every particle's position,
# velocity and stress after picReconstruct equal to the serial run's to 1e-12 of the array's
# largest value (shared nodes add the ranks' parts in rank order, the serial run particle by
# particle: round-off, doc/parallel.md), the same number of steps; and what a parallel run
# does not do yet, or a rank count the decomposition does not have, refused in one line.
# Usage: parallelRun.sh <source dir> <binary dir>
set -euo pipefail
source_dir=$1 binary_dir=$2
export PATH=$binary_dir/bin:$PATH GPIC_DIR=$source_dir OMP_NUM_THREADS=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*"; exit 1; }
mpi() { mpirun --oversubscribe --allow-run-as-root -np "$@"; }

prepare()  # tutorial case endTime writeInterval method ranks [coefficients]
{
    local c=$2
    cp -r "$source_dir/tutorials/$1" $c
    [ ! -x $c/Allclean ] || (cd $c && ./Allclean > /dev/null)
    python3 - $c/system/controlDict $3 $4 <<'END'
import re, sys
path, end, interval = sys.argv[1:]
s = open(path).read()
s = re.sub(r'\nendTime\s+[^;]+;', '\nendTime ' + end + ';', s)
s = re.sub(r'\nwriteInterval\s+[^;]+;', '\nwriteInterval ' + interval + ';', s)
open(path, 'w').write(s)
END
    cat > $c/system/decomposeParDict <<END
FoamFile { version 2.0; format ascii; class dictionary; location "system"; object decomposeParDict; }
numberOfSubdomains $6;
method $5;
${7:-}
END
    (cd $c && picInit > log.picInit && picDecompose > log.picDecompose)
}

compare()  # case ranks times...
{
    local c=$1 ranks=$2
    shift 2
    (cd $c && picSolver > log.serial 2>&1) || fail "$c serial: $(tail -1 $c/log.serial)"
    (cd $c && mpi $ranks picSolver -parallel > log.parallel 2>&1) || fail "$c on $ranks ranks: $(grep -m1 Error $c/log.parallel)"
    mkdir $c/rec && cp -r $c/system $c/constant $c/processor* $c/rec/
    picReconstruct -case $c/rec > /dev/null
    steps=$(grep -o '[0-9]* steps' $c/log.serial) psteps=$(grep -o '[0-9]* steps' $c/log.parallel)
    [ "$steps" = "$psteps" ] || fail "$c: serial $steps, parallel $psteps"
    grep -q "Parallel run: rank 0 of $ranks" $c/log.parallel || fail "$c: no parallel run reported"
    for t in "$@"; do
        python3 - $c/$t/particles.vtp $c/rec/$t/particles.vtp <<'END' || fail "$c time $t"
import os, sys
sys.path.insert(0, os.path.join(os.environ['GPIC_DIR'], 'etc', 'python'))
from gpicdat import read_particles
a, b = read_particles(sys.argv[1]), read_particles(sys.argv[2])
oa = sorted(range(len(a['id'])), key=lambda k: a['id'][k])
ob = sorted(range(len(b['id'])), key=lambda k: b['id'][k])
if [a['id'][k] for k in oa] != [b['id'][k] for k in ob]:
    sys.exit('not the same particles')
flat = lambda v: v if isinstance(v, tuple) else (v,)
worst = 0
for name in ('Points', 'velocity', 'stress', 'volume'):
    scale = max(abs(x) for k in oa for x in flat(a[name][k])) or 1.0
    for i, j in zip(oa, ob):
        worst = max(worst, max(abs(x - y) for x, y in zip(flat(a[name][i]), flat(b[name][j]))) / scale)
print('%s: %d particles, largest difference %.2e of the array\'s largest value' % (sys.argv[2], len(oa), worst))
sys.exit(0 if worst <= 1e-12 else 1)
END
    done
    # The function objects' rows (bodyMotion: sums over every rank's particles, rank 0 writes).
    for f in $(cd $c && find postProcessing -name '*.dat' 2> /dev/null); do
        python3 - $c/$f $c/rec/$f <<'END' || fail "$c: $f"
import sys
rows = [[[float(v) for v in line.split()] for line in open(p) if not line.startswith('#')] for p in sys.argv[1:]]
if len(rows[0]) != len(rows[1]) or not rows[0]:
    sys.exit('%d rows against %d' % (len(rows[0]), len(rows[1])))
# The rows are printed to 6 digits or more: alike where they differ by at most the last
# digit's rounding (1e-5 of the value), or by 1e-12 of the column's largest value, or of the
# file's (a column zero by symmetry, the sideways force on a centred footing, holds the
# round-off of the others).
bad = []
largest = max(abs(v) for r in rows[0] for v in r) or 1.0
for k in range(len(rows[0][0])):
    scale = max(abs(r[k]) for r in rows[0]) or 1.0
    bad += [(a[k], b[k]) for a, b in zip(*rows) if abs(a[k] - b[k]) > max(1e-5 * abs(a[k]), 1e-12 * scale, 1e-12 * largest)]
print('%s: %d rows, %d values apart beyond their printed digits %s' % (sys.argv[2], len(rows[0]), len(bad), bad[:3]))
sys.exit(0 if not bad else 1)
END
    done
    # The ranks' particles changed hands: rank 0 ends with another count than it started with.
    start=$(grep -o 'rank 0 of [0-9]*, [0-9]* particles' $c/log.parallel | grep -o '[0-9]* particles')
    end=$(grep -o '^End: .* steps, [0-9]* particles' $c/log.parallel | grep -o '[0-9]* particles$')
    [ "${moves:-yes}" = no ] || [ "$start" != "$end" ] || fail "$c: no particle moved between the ranks ($start, $end)"
}

prepare geotechnics/columnCollapse $work/column 0.1 0.05 hierarchical 2 "hierarchicalCoeffs { n (2 1); }"
compare $work/column 2 0.05 0.1
prepare geotechnics/cylinderCollapse $work/cylinder 0.06 0.03 scotch 4
compare $work/cylinder 4 0.03 0.06
prepare geotechnics/cylinderCollapse/axisymmetric $work/axisymmetric 0.1 0.05 scotch 2
compare $work/axisymmetric 2 0.05 0.1

# A rigid footing pushed into silt (one velocity field: the rigid nodes' loads summed over the
# nodes each rank owns), moved to straddle the two subdomains, with its forces rows. Not
# beyond 6 mm: the serial run itself, its gravity changed by one unit in the last place,
# departs by 1e-11 of the largest velocity at 10 mm (doc/parallel.md).
prepare geotechnics/footingBearing $work/footing 0.3 0.15 hierarchical 2 "hierarchicalCoeffs { n (2 1); }"
sed -i 's/min (0 1.2); max (0.2 1.32)/min (0.8 1.2); max (1.0 1.32)/' $work/footing/constant/bodies
(cd $work/footing && rm -rf processor* 0 && picInit > /dev/null && picDecompose > /dev/null)
moves=no compare $work/footing 2 0.15 0.3
# The blade with contact on 3 ranks (a field per body, the normals of its surface placed from
# every rank's particles), the first subdomain's side just ahead of the blade's face: pushed at
# 0.1 m/s, the blade and the sand ahead of it cross into the second.
prepare geotechnics/blade $work/blade 0.04 0.02 simple 3 "simpleCoeffs { n (3 1); }"
sed -i 's/velocity (0.005 0)/velocity (0.1 0)/' $work/blade/constant/rigidBodies $work/blade/processor*/constant/rigidBodies
compare $work/blade 3 0.02 0.04

# Decomposed again as the column spreads (every 100 steps where the larger subdomain holds
# more than 1.05 times the mean), with volumetricStrain cellMean: the subdomains' particle
# counts closer, the results still the serial run's.
prepare geotechnics/columnCollapse $work/spread 0.2 0.1 hierarchical 2 \
    "hierarchicalCoeffs { n (2 1); } redecomposeInterval 100; maxImbalance 1.05;"
# ... with the cell-mean dilatation, whose cells are each one rank's
for f in $work/spread/system/mpmSchemes $work/spread/processor*/system/mpmSchemes; do
    echo "volumetricStrain cellMean;" >> $f
done
compare $work/spread 2 0.1 0.2
grep -q "volumetric strain cellMean" $work/spread/log.parallel || fail "the spreading column ran without cellMean"
grep -q "decomposed again at step .*particles moved" $work/spread/log.parallel ||
    fail "the column was not decomposed again: $(grep 'Parallel run' $work/spread/log.parallel)"
grep "decomposed again" $work/spread/log.parallel
cmp -s $work/spread/processor0/constant/cellDecomposition $work/spread/processor1/constant/cellDecomposition ||
    fail "the ranks wrote different decompositions"

# Refused: a decomposition for another rank count; what a parallel run does not do yet.
c=$work/cylinder
out=$(cd $c && mpi 2 picSolver -parallel 2>&1) && fail "4 subdomains run on 2 ranks"
grep -q "decomposed into 4 subdomains, the run has 2 ranks" <<< "$out" || fail "message: $out"
c=$work/stages
cp -r "$source_dir/tutorials/stages/layeredFill" $c
(cd $c && ./Allclean > /dev/null && cp $work/column/system/decomposeParDict system/ && picInit > /dev/null && picDecompose > /dev/null)
out=$(cd $c && mpi 2 picSolver -parallel 2>&1) && fail "stages accepted in a parallel run"
grep -q "stages: not yet in a parallel run" <<< "$out" || fail "message: $out"
echo "parallelRun: ok"
