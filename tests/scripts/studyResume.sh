#!/bin/bash
# A study stopped after two of its four cases (-maxCases 2) and started again runs only the
# other two: the first two keep their runs (logs untouched) and the table has all four.
# A case that fails is reported with its error line and does not stop the others.
# Usage: studyResume.sh <source dir> <binary dir>
. "$(dirname "$0")/scratchRun.sh" "$@"
. "$(dirname "$0")/studyCase.sh"
cd "$work/case"
picStudy -quiet -maxCases 2 | tee first.txt
csv=studies/four/results.csv
[ "$(grep -c ',finished,$' $csv)" = 2 ] && [ "$(grep -c ',pending,$' $csv)" = 2 ] \
    || { echo "after -maxCases 2: expected 2 finished and 2 pending"; cat $csv; exit 1; }
first=$(grep ',finished,$' $csv | cut -d, -f1)
for c in $first; do md5sum studies/four/$c/log.picSolver studies/four/$c/studyStatus; done > before.md5
stat -c '%n %Y' studies/four/*/log.picSolver > before.times
sleep 1   # a rerun would leave a later modification time
picStudy -quiet | tee second.txt
grep -q "4 cases (factorial design), 2 to run" second.txt || { echo "the resumed study does not run 2 cases"; exit 1; }
for c in $first; do
    ! grep -q "running $c" second.txt || { echo "finished case $c ran again"; exit 1; }
done
md5sum -c --quiet before.md5 || { echo "a finished case's files changed"; exit 1; }
while read -r log time; do
    [ "$(stat -c %Y "$log")" = "$time" ] || { echo "$log rewritten"; exit 1; }
done < before.times
[ "$(grep -c ',finished,$' $csv)" = 4 ] || { echo "not all 4 cases finished"; cat $csv; exit 1; }
# resumed once more: nothing to run
picStudy -quiet > third.txt
grep -q "0 to run" third.txt || { echo "a finished study ran again"; exit 1; }

# A case whose sand is refused (phi above 90 degrees) fails with the solver's error line;
# its neighbour still finishes; picStudy exits 2 as picSolver does for a failed run.
cat > system/studyDict <<'DICT'
name        failing;
parameters  { phi { values (35 95); file constant/materials; entry sand/phi; } }
results     { drag { functionObject forces; column blade:Fx; statistic last; } }
DICT
code=0; picStudy -quiet > failing.txt || code=$?
cat failing.txt
[ $code = 2 ] || { echo "expected exit status 2 for a failed case, got $code"; exit 1; }
csv=studies/failing/results.csv
grep -q '^phi35,35,[-0-9.e]*,[0-9]*,[0-9]*,[0-9.]*,finished,$' $csv || { echo "phi 35 did not finish"; cat $csv; exit 1; }
error=$(grep '^phi95,' $csv | cut -d, -f7-)
echo "$error" | grep -q "^failed,Error: constant/materials:[0-9]*: .*phi" \
    || { echo "phi 95: expected failed with the error line naming constant/materials and phi: $error"; exit 1; }
grep -q "phi95 failed: Error: constant/materials" failing.txt || { echo "the failure is not reported"; exit 1; }
echo "resumed without rerunning finished cases; a failed case reported with its error line"
