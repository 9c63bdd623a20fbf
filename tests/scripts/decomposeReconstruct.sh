#!/bin/bash
# picDecompose and picReconstruct (doc/parallel.md) on a plane and a 3D tutorial: the
# particles of a time split over the subdomains by each method and merged back are the same
# particles, bit for bit (picInit's time 0, in id order: the same file; a time a run wrote,
# sorted by cell: the same arrays particle by particle); each subdomain holds the particles
# of the cells it owns; and the mistakes a user makes are refused in one line.
# Usage: decomposeReconstruct.sh <source dir> <binary dir>
set -euo pipefail
source_dir=$1 binary_dir=$2
export PATH=$binary_dir/bin:$PATH GPIC_DIR=$source_dir
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*"; exit 1; }

dict()  # case method subdomains [coefficients]
{
    cat > $1/system/decomposeParDict <<END
FoamFile { version 2.0; format ascii; class dictionary; location "system"; object decomposeParDict; }
numberOfSubdomains $3;
method $2;
${4:-}
END
}

# Every array of two particle files equal, particle by particle matched by id.
same_particles()  # a.vtp b.vtp
{
    python3 - "$1" "$2" <<'END'
import sys
sys.path.insert(0, sys.argv[0] and __import__('os').path.join(__import__('os').environ['GPIC_DIR'], 'etc', 'python'))
from gpicdat import read_particles
a, b = read_particles(sys.argv[1]), read_particles(sys.argv[2])
if sorted(a) != sorted(b):
    sys.exit('arrays differ: %s / %s' % (sorted(a), sorted(b)))
oa = sorted(range(len(a['id'])), key=lambda k: a['id'][k])
ob = sorted(range(len(b['id'])), key=lambda k: b['id'][k])
for name in a:
    if [a[name][k] for k in oa] != [b[name][k] for k in ob]:
        sys.exit('array %s differs' % name)
print('%d particles, %d arrays alike' % (len(oa), len(a)))
END
}

for tutorial in geotechnics/columnCollapse geotechnics/cylinderCollapse; do
    c=$work/${tutorial##*/}
    cp -r "$source_dir/tutorials/$tutorial" $c
    (cd $c && ./Allclean > /dev/null && picInit > log.picInit)
    dims=$(grep -c "nCells *([0-9]* [0-9]* [0-9]*)" $c/constant/grid || true)
    if [ "$dims" = 1 ]; then n="(2 1 2)"; else n="(2 2)"; fi
    for method in simple hierarchical scotch; do
        case $method in
            simple) dict $c simple 4 "simpleCoeffs { n $n; }" ;;
            hierarchical) dict $c hierarchical 4 "hierarchicalCoeffs { n $n; }" ;;
            scotch) dict $c scotch 3 ;;
        esac
        picDecompose -case $c -force > $c/log.picDecompose || fail "$tutorial $method: picDecompose: $(tail -1 $c/log.picDecompose)"
        mv $c/0 $c/0.serial
        picReconstruct -case $c > $c/log.picReconstruct || fail "$tutorial $method: picReconstruct"
        cmp -s $c/0/particles.vtp $c/0.serial/particles.vtp || fail "$tutorial $method: time 0 differs after the round trip"
        rm -rf $c/0 && mv $c/0.serial $c/0
        echo "$tutorial $method: $(tail -1 $c/log.picDecompose)"
    done
    # Each subdomain's particles lie in the cells it owns (the owner file against positions).
    python3 - $c <<'END'
import os, re, sys
sys.path.insert(0, os.path.join(os.environ['GPIC_DIR'], 'etc', 'python'))
from gpicdat import read_particles
case = sys.argv[1]
grid = re.sub(r'//[^\n]*', '', open(os.path.join(case, 'constant', 'grid')).read())
origin = [float(v) for v in re.search(r'origin\s*\(([^)]*)\)', grid).group(1).split()]
cells = [int(v) for v in re.search(r'nCells\s*\(([^)]*)\)', grid).group(1).split()]
size = re.search(r'cellSize\s+([^;]+);', grid).group(1).strip('() ').split()
h = [float(v) for v in size] * (len(cells) if len(size) == 1 else 1)
text = open(os.path.join(case, 'processor0', 'constant', 'cellDecomposition')).read()
owner = [int(v) for v in text[text.index('owner'):].split('(')[1].split(')')[0].split()]
for k in range(int(re.search(r'numberOfSubdomains (\d+)', text).group(1))):
    for x in read_particles(os.path.join(case, 'processor%d' % k, '0', 'particles.vtp'))['Points']:
        c, stride = 0, 1
        for a in range(len(cells)):
            i = min(max(int((x[a] - origin[a]) // h[a]), 0), cells[a] - 1)
            c += i * stride
            stride *= cells[a]
        if owner[c] != k:
            sys.exit('a particle of processor%d lies in a cell of subdomain %d' % (k, owner[c]))
END
done

# A time a run wrote (the particles sorted by cell, not by id): the same arrays come back.
c=$work/columnCollapse
sed -i -E 's/^endTime .*/endTime 0.04;/; s/^writeInterval .*/writeInterval 0.02;/' $c/system/controlDict
(cd $c && picSolver > log.picSolver) || fail "picSolver: $(tail -1 $c/log.picSolver)"
dict $c hierarchical 2 "hierarchicalCoeffs { n (2 1); }"
picDecompose -case $c -force -time 0.04 > $c/log.picDecompose
mv $c/0.04 $c/serial
picReconstruct -case $c -latestTime > $c/log.picReconstruct
same_particles $c/0.04/particles.vtp $c/serial/particles.vtp || fail "time 0.04 differs after the round trip"
picReconstruct -case $c | grep -q "0.04: the case holds it already" || fail "a time the case holds is not left alone"

# Mistakes: one line naming the file and the keyword, exit 1.
dict $c simple 4 "simpleCoeffs { n (2 3); }"
out=$(picDecompose -case $c -force 2>&1) && fail "counts that do not multiply to the subdomains accepted"
grep -q "system/decomposeParDict:[0-9]*: keyword 'n' in .*multiply to 6, not numberOfSubdomains 4" <<< "$out" || fail "message: $out"
dict $c hierarchical 2 "hierarchicalCoeffs { n (2 1); }"
out=$(picDecompose -case $c 2>&1) && fail "a second decomposition over the first accepted"
grep -q "is decomposed already" <<< "$out" || fail "message: $out"
rm -rf $c/processor*
out=$(picReconstruct -case $c 2>&1) && fail "a case without processor0 reconstructed"
grep -q "no processor0" <<< "$out" || fail "message: $out"
echo "decomposeReconstruct: ok"
