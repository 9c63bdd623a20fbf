#!/bin/bash
# picSolver -parallel under mpirun against the serial run (doc/parallel.md): the two disks on
# 2 and 4 ranks, a plane column
# of sand on 2 ranks (hierarchical), a 3D cylinder of sand on 4 (scotch) and its axisymmetric
# twin on 2 (scotch), each collapsing; a rigid footing on 2 ranks and the blade with contact
# on 3, pushed into soil; the silo in its stages on 2, decomposed again as it empties; a fill
# in layers on 2, and its restart; a loaded thick cylinder on 2
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

withFunctions()  # case entries...: function objects added to the case's and its subdomains' controlDicts
{
    local c=$1
    shift
    for f in $c/system/controlDict $c/processor*/system/controlDict; do
        python3 - $f "$@" <<'END'
import re, sys
s = open(sys.argv[1]).read()
s, n = re.subn(r'\nfunctions\s*\{', '\nfunctions\n{\n    ' + '\n    '.join(sys.argv[2:]), s)
if n != 1:
    sys.exit('no functions in ' + sys.argv[1])
open(sys.argv[1], 'w').write(s)
END
    done
}

stacked()  # case redecomposeInterval maxImbalance: 2 subdomains one above the other, decomposed
{
    cat > $1/system/decomposeParDict <<END
FoamFile { version 2.0; format ascii; class dictionary; location "system"; object decomposeParDict; }
numberOfSubdomains 2;
method hierarchical;
hierarchicalCoeffs { n (1 2); }
redecomposeInterval $2;
maxImbalance $3;
END
    (cd $1 && picInit > /dev/null && picDecompose > /dev/null)
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
    # ulp=yes: a scene whose serial run is itself this sensitive to round-off. The serial run
    # again with gravity one unit in the last place larger sets the bound: the parallel run
    # may be apart from the serial one by ten times as much (and always by 1e-12).
    local perturbed=
    if [ "${ulp:-no}" = yes ]; then
        perturbed=$c/ulp
        mkdir $perturbed && cp -r $c/system $c/constant $c/0 $perturbed/
        python3 - $perturbed/constant/g <<'END'
import math, re, sys
s = open(sys.argv[1]).read()
m = re.search(r'value\s*\(([^)]*)\)', s)
g = [float(v) for v in m.group(1).split()]
k = max(range(len(g)), key=lambda i: abs(g[i]))
g[k] = math.nextafter(g[k], 2 * g[k])
open(sys.argv[1], 'w').write(s[:m.start()] + 'value (' + ' '.join(repr(v) for v in g) + ')' + s[m.end():])
END
        (cd $perturbed && picSolver > log.serial 2>&1) || fail "$perturbed: $(tail -1 $perturbed/log.serial)"
    fi
    # Each array to its largest value over the times compared: an array still round-off (the
    # stress of the two disks before they meet) is measured against what it comes to.
    python3 - $c ${perturbed:-none} "$@" <<'END' || fail "$c"
import os, sys
sys.path.insert(0, os.path.join(os.environ['GPIC_DIR'], 'etc', 'python'))
from gpicdat import read_particles
case, perturbed, times = sys.argv[1], sys.argv[2], sys.argv[3:]
# (and a polar material's micro-rotation rate and couple stress)
names = [n for n in ('Points', 'velocity', 'stress', 'volume', 'microRotationRate', 'coupleStress')
         if n in read_particles(os.path.join(case, times[0], 'particles.vtp'))]
flat = lambda v: v if isinstance(v, tuple) else (v,)
def byId(path):
    p = read_particles(path)
    order = sorted(range(len(p['id'])), key=lambda k: p['id'][k])
    return [p['id'][k] for k in order], {n: [flat(p[n][k]) for k in order] for n in names}
serial = {t: byId(os.path.join(case, t, 'particles.vtp')) for t in times}
scale = {n: max(abs(x) for t in times for v in serial[t][1][n] for x in v) or 1.0 for n in names}
def apart(t, other):
    ids, arrays = byId(other)
    if ids != serial[t][0]:
        sys.exit('%s: not the same particles (%d, %d)' % (other, len(ids), len(serial[t][0])))
    return max(max(abs(x - y) for u, v in zip(serial[t][1][n], arrays[n]) for x, y in zip(u, v)) / scale[n] for n in names)
bad = False
for t in times:
    worst = apart(t, os.path.join(case, 'rec', t, 'particles.vtp'))
    bound, said = 1e-12, ''
    if perturbed != 'none':
        alone = apart(t, os.path.join(perturbed, t, 'particles.vtp'))
        bound = max(bound, 10 * alone)
        said = ' (the serial run with gravity one ulp larger: %.2e)' % alone
    print('%s/rec/%s: %d particles, largest difference %.2e of the array\'s largest value%s' % (case, t, len(serial[t][0]), worst, said))
    bad = bad or worst > bound
sys.exit(1 if bad else 0)
END
    # The function objects' rows (bodyMotion: sums over every rank's particles, rank 0 writes).
    # The stages' rows: the same stages ending at the same steps, for the same reasons.
    if [ -f $c/postProcessing/stages.dat ]; then
        diff $c/postProcessing/stages.dat $c/rec/postProcessing/stages.dat || fail "$c: stages.dat"
    fi
    for f in $(cd $c && find postProcessing -name '*.dat' ! -name stages.dat 2> /dev/null); do
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
    # ParaView's index of the decomposed run: every rank's particles at each time written.
    python3 - $c/processors.pvd $ranks "$@" <<'END' || fail "$c: processors.pvd"
import os, sys, xml.etree.ElementTree as ET
path, ranks, times = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
sets = ET.parse(path).getroot().iter('DataSet')
files = {d.get('file') for d in sets}
missing = ['processor%d/%s/particles.vtp' % (r, t) for r in range(ranks) for t in times
           if 'processor%d/%s/particles.vtp' % (r, t) not in files]
absent = [f for f in files if not os.path.exists(os.path.join(os.path.dirname(path), f))]
print('%s: %d files, %d of the written times missing, %d absent' % (path, len(files), len(missing), len(absent)))
sys.exit(1 if missing or absent else 0)
END
    # The ranks' particles changed hands: rank 0 ends with another count than it started with.
    start=$(grep -o 'rank 0 of [0-9]*, [0-9]* particles' $c/log.parallel | grep -o '[0-9]* particles')
    end=$(grep -o '^End: .* steps, [0-9]* particles' $c/log.parallel | grep -o '[0-9]* particles$')
    [ "${moves:-yes}" = no ] || [ "$start" != "$end" ] || fail "$c: no particle moved between the ranks ($start, $end)"
}

# The seed's two elastic disks (USF, one velocity field) meeting on the subdomains' border,
# on 2 ranks and on 4, through the collision and apart again.
prepare verification/twoDisks $work/disks2 3 1 hierarchical 2 "hierarchicalCoeffs { n (2 1); }"
compare $work/disks2 2 1 2 3
prepare verification/twoDisks $work/disks4 3 1 hierarchical 4 "hierarchicalCoeffs { n (2 2); }"
compare $work/disks4 4 1 2 3
prepare geotechnics/columnCollapse $work/column 0.1 0.05 hierarchical 2 "hierarchicalCoeffs { n (2 1); }"
compare $work/column 2 0.05 0.1
# ... with `transfer XPIC` (order 5: four more scatters a step, each completed over the ranks)
prepare geotechnics/columnCollapse $work/xpic 0.1 0.05 hierarchical 2 "hierarchicalCoeffs { n (2 1); }"
sed -i 's/^transfer .*/transfer XPIC;/; /^flipRelaxationTime/d' $work/xpic/system/mpmSchemes $work/xpic/processor*/system/mpmSchemes
compare $work/xpic 2 0.05 0.1
grep -q "XPIC" $work/xpic/log.parallel || fail "the column ran without XPIC"
# ... of a polar material (Cosserat Drucker-Prager: the rotation's inertia, spin momentum and
# moment completed over the ranks like the engine's own fields)
prepare geotechnics/columnCollapse $work/polar 0.1 0.05 hierarchical 2 "hierarchicalCoeffs { n (2 1); }"
for f in $work/polar/constant/materials $work/polar/processor*/constant/materials; do
    sed -i 's/^sand .*/sand { type cosseratDruckerPrager; rho 2650; G 3.85e5; nu 0.3; l 0.01; phi 30; psi 0; }/' $f
done
compare $work/polar 2 0.05 0.1
grep -q "cosseratDruckerPrager" $work/polar/log.parallel || fail "the column ran without its polar material"
# ... with `transfer APIC`, whose serial run departs from itself by 1e-12 and more, in bursts,
# with gravity changed by one ulp (a particle on a grid line: its D_p near singular).
prepare geotechnics/columnCollapse $work/apic 0.1 0.05 hierarchical 2 "hierarchicalCoeffs { n (2 1); }"
sed -i 's/^transfer .*/transfer APIC;/; /^flipRelaxationTime/d' $work/apic/system/mpmSchemes $work/apic/processor*/system/mpmSchemes
ulp=yes compare $work/apic 2 0.05 0.1
prepare geotechnics/cylinderCollapse $work/cylinder 0.06 0.03 scotch 4
compare $work/cylinder 4 0.03 0.06
prepare geotechnics/cylinderCollapse/axisymmetric $work/axisymmetric 0.1 0.05 scotch 2
compare $work/axisymmetric 2 0.05 0.1

# A rigid ball drawn as STL, load-driven and turning (weighted, freeRotation), rolling down an
# elastic slab in 3D on 2 ranks (contact with its facets' normals and separationCutoff): the
# load on it summed over the ranks' owned nodes moves it alike on every rank, its pose from
# every rank's particles; its forces and (3D) wear rows too.
prepare contact/inclinedSphere/rigidBall $work/ball 0.1 0.05 hierarchical 2 "hierarchicalCoeffs { n (2 1 1); }"
withFunctions $work/ball "forces { type forces; bodies (sphere); writeInterval 20; }" \
    "wear { type toolWear; body sphere; wearCoefficient 1e-4; hardness 2e9; writeInterval 20; }"
compare $work/ball 2 0.05 0.1

# A rigid footing pushed into silt (one velocity field: the rigid nodes' loads summed over the
# nodes each rank owns), moved to straddle the two subdomains, with its forces rows. Not
# beyond 6 mm: the serial run itself, its gravity changed by one unit in the last place,
# departs by 1e-11 of the largest velocity at 10 mm (doc/parallel.md).
prepare geotechnics/footingBearing $work/footing 0.3 0.15 hierarchical 2 "hierarchicalCoeffs { n (2 1); }"
sed -i 's/min (0 1.2); max (0.2 1.32)/min (0.8 1.2); max (1.0 1.32)/' $work/footing/constant/bodies
(cd $work/footing && rm -rf processor* 0 && picInit > /dev/null && picDecompose > /dev/null)
moves=no compare $work/footing 2 0.15 0.3
# The blade with contact on 3 ranks (a field per body, the normals of its surface placed from
# every rank's particles), the first subdomain's side just ahead of the blade's face: pushed
# 4 mm at 0.5 m/s, the blade and the sand ahead of it cross into the second.
prepare geotechnics/blade $work/blade 0.008 0.004 simple 3 "simpleCoeffs { n (3 1); }"
sed -i 's/velocity (0.005 0)/velocity (0.5 0)/' $work/blade/constant/rigidBodies $work/blade/processor*/constant/rigidBodies
# ... the sand in a box ahead of it (toolFill: a sum over every rank's particles) and the wear
# of its face (toolWear: each step's wear from the nodes each rank owns, added over the ranks)
sed -i 's/writeInterval 1250;/writeInterval 100;/' $work/blade/system/controlDict $work/blade/processor*/system/controlDict
withFunctions $work/blade \
    "fill { type toolFill; body blade; bodies (soil); writeInterval 100; region { type rectangle; min (0.32 0.3); max (0.42 0.45); } }" \
    "wear { type toolWear; body blade; wearCoefficient 1e-4; hardness 2e9; resolution 0.01; writeInterval 100; faces { front { from (0.32 0.19); to (0.32 0.45); } } }"
compare $work/blade 3 0.004 0.008

# The silo (seed 4.6) in its two stages, a damped settling with the outlet closed and the
# discharge through it, on 2 ranks one above the other, decomposed again as it empties; its
# massFlow and stages rows. The settling is cut at 0.02 s: near rest the serial run alone is
# chaotic (with gravity changed by one unit in the last place its particles' velocities are
# 40 % of the largest apart at 0.02 s, doc/parallel.md).
c=$work/silo
cp -r "$source_dir/tutorials/geotechnics/silo" $c
(cd $c && ./Allclean > /dev/null)
python3 - $c <<'END'
import re, sys
c = sys.argv[1]
def edit(path, pairs):
    s = open(path).read()
    for a, b in pairs:
        if not re.search(a, s):
            sys.exit('%s: no %s' % (path, a))
        s = re.sub(a, b, s)
    open(path, 'w').write(s)
edit(c + '/constant/grid', [(r'cellSize\s+[^;]+;', 'cellSize 0.01;'), (r'nCells\s+[^;]+;', 'nCells (10 30);')])
edit(c + '/system/controlDict', [(r'\ndeltaT\s+[^;]+;', '\ndeltaT 1e-4;'), (r'\nwriteInterval\s+[^;]+;', '\nwriteInterval 0.1;'),
     (r'maxTime 3;', 'maxTime 0.02;'), (r'duration 0.5;', 'duration 0.2;')])
END
stacked $c 200 1.05
compare $c 2 0.02 0.1 0.22
grep -q "decomposed again at step" $c/log.parallel || fail "the silo was not decomposed again as it emptied"
grep "decomposed again" $c/log.parallel

# A fill in 20 layers (geostaticFill, stages/layeredFill) on 2 ranks one above the other: each
# rank keeps the sleeping particles of its cells, a layer wakes on every rank alike, and the
# ranks are decomposed again as the layers come (sleeping particles moved too). Each layer
# ends when the fastest particle falls below 1e-5 m/s, a decision that the serial run with
# gravity one ulp larger already takes at other steps; the parallel run takes every one at
# the serial run's step (its stages' rows), the particles alike to 5e-14 at the first write.
c=$work/fill
cp -r "$source_dir/tutorials/stages/layeredFill" $c
(cd $c && ./Allclean > /dev/null)
sed -i 's/maxTime 1; }/maxTime 0.05; }/' $c/system/controlDict
stacked $c 100 1.1
moves=no compare $c 2 0.0625
grep -q "decomposed again at step" $c/log.parallel || fail "the fill was not decomposed again"
# The sleeping particles merged back: the serial run's at 0.25 s, id for id.
python3 - $c/0.25/dormant.vtp $c/rec/0.25/dormant.vtp <<'END' || fail "fill: dormant.vtp"
import os, sys
sys.path.insert(0, os.path.join(os.environ['GPIC_DIR'], 'etc', 'python'))
from gpicdat import read_particles
a, b = (sorted(read_particles(f)['id']) for f in sys.argv[1:])
print('dormant.vtp at 0.25 s: %d sleeping particles, %s' % (len(a), 'alike' if a == b else 'apart'))
sys.exit(0 if a == b and a else 1)
END
# A restart in parallel from the reconstructed time 0.25, decomposed anew with its sleeping
# particles: the same stages, ending at the same steps, as the serial run straight through.
mkdir $c/restart && cp -r $c/system $c/constant $c/rec/0 $c/rec/0.25 $c/restart/
(cd $c/restart && picDecompose -time 0.25 > log.picDecompose && mpi 2 picSolver -parallel > log.parallel 2>&1) ||
    fail "fill restart: $(grep -m1 Error $c/restart/log.parallel)"
grep -q "dormant.vtp" $c/restart/log.picDecompose || fail "fill restart: no sleeping particles decomposed"
diff $c/postProcessing/stages.dat $c/restart/processor0/postProcessing/stages.dat || fail "fill restart: stages.dat"

# A pressure on the inside of a thick cylinder (surfacePressure, axisymmetric) on 2 ranks one
# above the other: the loads choose their particles among every rank's and each rank finds its
# loaded ones by id. Undamped: local damping turns with the sign of each nodal velocity, and
# near rest the serial run alone departs from itself by 6e-2 of the largest velocity with the
# pressure one ulp larger (doc/parallel.md).
prepare verification/thickCylinder $work/tube 0.12 0.06 hierarchical 2 "hierarchicalCoeffs { n (1 2); }"
sed -i 's/^damping .*//; s/^writeControl .*/writeControl adjustableRunTime;/' $work/tube/system/controlDict $work/tube/processor*/system/controlDict
moves=no compare $work/tube 2 0.06 0.12

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

# A stop signal that reaches one rank alone (as a scheduler's may): every rank stops at the end
# of the same step and writes it, none waits for the others.
prepare geotechnics/columnCollapse $work/stop 100 50 hierarchical 2 "hierarchicalCoeffs { n (2 1); }"
c=$work/stop
(cd $c && exec mpirun --oversubscribe --allow-run-as-root -np 2 picSolver -parallel > log.parallel 2>&1) &
runner=$!
for i in $(seq 150); do grep -q "Parallel run: rank 0 of" $c/log.parallel 2> /dev/null && break; sleep 0.2; done
sleep 1
ranks=($(pgrep -P $runner))
[ ${#ranks[@]} = 2 ] || fail "stop: mpirun's two ranks not found (${ranks[*]:-none})"
kill -TERM ${ranks[1]}
status=0
wait $runner || status=$?
[ $status != 0 ] || fail "stop: the run ended without the signal"
grep -q "run stopped by SIGTERM" $c/log.parallel || fail "stop: $(grep -m1 Error $c/log.parallel)"
# (the two ranks' messages may share a line of the log: the written states tell)
newest() { (cd $1 && ls -d [0-9]* | sort -g | tail -1); }
t0=$(newest $c/processor0) t1=$(newest $c/processor1)
step() { grep -o 'index *[0-9]*' $c/processor$1/$2/uniform/time; }
[ "$t0" = "$t1" ] && [ "$t0" != 0 ] && [ "$(step 0 $t0)" = "$(step 1 $t1)" ] ||
    fail "stop: the ranks stopped apart: times $t0 ($(step 0 $t0)) and $t1 ($(step 1 $t1))"
echo "stop: both ranks wrote time $t0, $(step 0 $t0)"

# Refused: a decomposition for another rank count.
c=$work/cylinder
out=$(cd $c && mpi 2 picSolver -parallel 2>&1) && fail "4 subdomains run on 2 ranks"
grep -q "decomposed into 4 subdomains, the run has 2 ranks" <<< "$out" || fail "message: $out"

echo "parallelRun: ok"
