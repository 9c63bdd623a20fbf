#!/bin/bash
# picStudy -dryRun writes each case of a study with only the study's entries changed: every
# line of every file of each case is compared with the base case's, the changed ones with
# the values the parameters give; nothing runs. A Latin hypercube puts one sample in each
# stratum of a range and repeats itself with the same seed.
# Usage: studyDryRun.sh <source dir> <binary dir>
. "$(dirname "$0")/scratchRun.sh" "$@"
. "$(dirname "$0")/studyCase.sh"
cd "$work/case"
picStudy -dryRun > dryRun.txt
cat dryRun.txt
python3 - "$work/case" <<'PY'
import os, sys
base = sys.argv[1]
study = os.path.join(base, 'studies', 'four')

def lines(path):
    with open(path) as f:
        return f.read().splitlines()

def expected(file, depth, mu):
    """The base file's lines with the study's entries set by hand for (depth, mu)."""
    foot = '%g' % round(0.4 - depth, 12)
    out = []
    for line in lines(os.path.join(base, file)):
        if file == 'constant/bodies' and 'points' in line:
            line = line.replace('(0.325 0.2) (0.3 0.2)', '(0.325 %s) (0.3 %s)' % (foot, foot))
        elif file == 'constant/bodies' and 'min (0.3 0.2)' in line:
            line = line.replace('min (0.3 0.2)', 'min (0.3 %s)' % foot)
        elif file == 'system/controlDict' and 'from (0.325 0.2)' in line:
            line = line.replace('from (0.325 0.2)', 'from (%s)' % ('0.325 ' + foot))
        elif file == 'constant/contactProperties' and line.startswith('mu '):
            line = line.replace('0.2', '%g' % mu)
        out.append(line)
    return out

files = [os.path.join(d, f) for d in ('system', 'constant')
         for f in sorted(os.listdir(os.path.join(base, d))) if f != 'studyDict']
cases = sorted(os.listdir(study))
want = sorted('depth%g_mu%g' % (d, m) for d in (0.15, 0.2) for m in (0.1, 0.3))
assert cases == want, (cases, want)
changed = 0
for name in cases:
    depth, mu = float(name[5:name.index('_')]), float(name[name.index('_mu') + 3:])
    case = os.path.join(study, name)
    for file in files:
        got, ref = lines(os.path.join(case, file)), expected(file, depth, mu)
        assert len(got) == len(ref), (name, file, 'line count')
        for k, (a, b) in enumerate(zip(got, ref)):
            assert a == b, '%s/%s:%d: %r, expected %r' % (name, file, k + 1, a, b)
        changed += sum(a != b for a, b in zip(got, lines(os.path.join(base, file))))
    assert not os.path.exists(os.path.join(case, 'system', 'studyDict')), name
    for ran in ('0', 'log.picInit', 'log.picSolver', 'postProcessing', 'studyStatus'):
        assert not os.path.exists(os.path.join(case, ran)), (name, ran, 'a dry run runs nothing')
# depth 0.15: the sand's notch, the blade's foot, the face and mu; depth 0.2 is the base's
assert changed == 2 * 4 + 2 * 1, changed
print('dry run: %d cases, %d changed lines, every other line as in the base case' % (len(cases), changed))
PY
grep -q "^depth0.15_mu0.1:" dryRun.txt && grep -q "^+mu          0.1;" dryRun.txt \
    || { echo "the dry run does not list the cases and their diffs"; exit 1; }

# A Latin hypercube of 5 samples: one depth in each fifth of [0.15, 0.2], mu from its list.
sed -i 's/^design .*/design latinHypercube; samples 5; seed 7;/; s/^name .*/name lhs;/' system/studyDict
picStudy -dryRun -quiet > lhs1.txt
picStudy -dryRun -quiet > lhs2.txt
cmp -s lhs1.txt lhs2.txt || { echo "the same seed gave other samples"; exit 1; }
python3 - studies/lhs <<'PY'
import os, re, sys
depths, mus = [], []
for name in sorted(os.listdir(sys.argv[1])):
    text = open(os.path.join(sys.argv[1], name, 'constant', 'bodies')).read()
    depths.append(0.4 - float(re.search(r'min \(0\.3 ([0-9.e-]+)\)', text).group(1)))
    mus.append(float(re.search(r'^mu\s+([0-9.e-]+);', open(os.path.join(sys.argv[1], name, 'constant', 'contactProperties')).read(), re.M).group(1)))
strata = sorted(int((d - 0.15) / 0.05 * 5 - 1e-9) for d in depths)
assert len(depths) == 5 and strata == list(range(5)), (depths, strata)
assert set(mus) <= {0.1, 0.3} and len(set(mus)) == 2, mus
print('Latin hypercube: depths %s, mu %s' % (' '.join('%.4f' % d for d in depths), ' '.join('%g' % m for m in mus)))
PY
