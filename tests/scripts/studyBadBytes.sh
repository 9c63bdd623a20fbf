#!/bin/bash
# picStudy on files that are not UTF-8 text, and on a large design: a Latin-1 byte in
# system/studyDict or in a base-case file the study rewrites, and a binary studyDict, are one
# line naming the file and the line (exit 1), not a traceback; a design of more than 10 000
# cases is warned with its disk use, and the writing of many cases shows its progress.
# Usage: studyBadBytes.sh <source dir> <binary dir>
. "$(dirname "$0")/scratchRun.sh" "$@"
. "$(dirname "$0")/studyCase.sh"
cd "$work/case"
cp system/studyDict studyDict.good
fail() { echo "studyBadBytes: $*"; exit 1; }

# refused <file label> <line> <words>: picStudy -dryRun exits 1 with that one line
refused() {
    local code=0
    picStudy -dryRun > out.txt 2> err.txt || code=$?
    [ "$code" = 1 ] || fail "exit $code, expected 1: $(cat err.txt)"
    [ "$(wc -l < err.txt)" = 1 ] || fail "expected one line: $(cat err.txt)"
    grep -q "^Error: $1:$2: .*$3" err.txt || fail "expected '$1:$2: ... $3': $(cat err.txt)"
    [ -e studies/four ] && fail "a case was written"
    echo "refused: $(cat err.txt)"
}
# A Latin-1 e-acute (0xe9) in a comment on line 4.
sed -i '4s/$/  \/\/ caf\xe9/' system/studyDict
refused system/studyDict 4 'byte 0xe9 is not UTF-8'
# A binary file in place of the dictionary.
printf 'FoamFile\n\x7fELF\x02\x01\x01\x00\x00' > system/studyDict
refused system/studyDict 2 'a NUL byte: not a text file'
# A Latin-1 byte in a file of the base case that the study rewrites.
cp studyDict.good system/studyDict
printf '// r\xe9glage\n' >> constant/contactProperties
refused constant/contactProperties "$(wc -l < constant/contactProperties)" 'byte 0xe9 is not UTF-8'
sed -i '$d' constant/contactProperties

# 10001 cases (mu in 10001 values): warned at once with the size; -maxCases 200 writes 200
# of them and says how far it has got.
cat > system/studyDict <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; location "system"; object studyDict; }
name        many;
design      factorial;
parameters
{
    mu      { range { start 0.1; end 0.3; count 10001; } file constant/contactProperties; entry mu; }
}
results
{
    frontForce  { functionObject forces; column front:Fx; scale -1; statistic max; }
}
executor    local;
DICT
picStudy -dryRun -quiet -maxCases 200 > out.txt 2> err.txt || fail "a large dry run failed: $(cat err.txt)"
grep -q "^Warning: system/studyDict: the design makes 10001 cases (more than 10000), each a copy of the base case of about .* in all" \
    err.txt || fail "no size warning: $(cat err.txt)"
grep -q "^Writing cases: 100 of 200$" out.txt && grep -q "^Writing cases: 200 of 200$" out.txt ||
    fail "no progress lines: $(grep -v '^ ' out.txt | head -5)"
[ "$(ls studies/many | wc -l)" = 200 ] || fail "not 200 cases written: $(ls studies/many | wc -l)"
echo "studyBadBytes: ok"
