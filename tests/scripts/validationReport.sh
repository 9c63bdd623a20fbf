#!/bin/bash
# The validation report generator on two quick tutorials (a copy of tutorials/): it must run
# their ladders and write a report with the summary, each ladder's table of reference, ours,
# errors, particles, steps and wall time, and the error-against-wall-time plots.
# Usage: validationReport.sh <source dir> <binary dir>
. "$(dirname "$0")/scratchRun.sh" "$@"
mkdir -p "$work/tutorials/verification" "$work/tutorials/materials"
cp "$source_dir/tutorials/Allvalidate" "$work/tutorials/"
cp -r "$source_dir/tutorials/verification/elasticBar" "$work/tutorials/verification/"
cp -r "$source_dir/tutorials/materials/oedometerPoint" "$work/tutorials/materials/"
"$work/tutorials/Allvalidate" -output "$work/report"
report=$work/report/report.md
grep -q "^## Summary" "$report" || { echo "no summary"; exit 1; }
for case in elasticBar-uGIMP elasticBar-bilinear oedometerPoint-associated-psi10; do
    rows=$(grep -c "^| $case |" "$report" || true)
    [ "$rows" -ge 3 ] || { echo "expected the summary and ladder rows of $case, found $rows"; exit 1; }
done
for png in verification_elasticBar/errorAgainstWallTime.png materials_oedometerPoint/errorAgainstWallTime.png \
           verification_elasticBar/bar.png; do
    [ -s "$work/report/$png" ] || { echo "missing $png"; exit 1; }
    grep -q "($png)" "$report" || { echo "report does not show $png"; exit 1; }
done
# A report built up over runs: elasticBar's results of the first run stay when only
# oedometerPoint runs again (its own rows gone from the tutorial), marked as earlier; a new
# report directory lists elasticBar as not run.
rm -f "$work/tutorials/verification/elasticBar/validation.dat"
"$work/tutorials/Allvalidate" -case oedometerPoint -output "$work/report" > /dev/null
grep -q "^| elasticBar-uGIMP |" "$report" || { echo "elasticBar's earlier rows lost"; exit 1; }
grep -q "^Results of an earlier run: .* UTC, Allrun ok" "$report" || { echo "earlier run not marked"; exit 1; }
[ -s "$work/report/verification_elasticBar/bar.png" ] || { echo "earlier picture lost"; exit 1; }
"$work/tutorials/Allvalidate" -case oedometerPoint -output "$work/other" > /dev/null
grep -q "Not run at this setting yet" "$work/other/report.md" || { echo "missing tutorial not listed"; exit 1; }
# A tutorial run with chosen Allrun arguments: the report and the stored stamp name them.
"$work/tutorials/Allvalidate" -case oedometerPoint -args=-full -output "$work/report" > /dev/null
grep -q '^Run now: `Allrun -full`' "$report" || { echo "the Allrun arguments not in the report"; exit 1; }
grep -q "UTC, Allrun -full ok" "$work/report/materials_oedometerPoint/run.txt" || { echo "stamp lacks the arguments"; exit 1; }
grep -q "^| oedometerPoint-associated-psi10 | 30000steps " "$report" || { echo "the -full ladder did not run"; exit 1; }
if "$work/tutorials/Allvalidate" -args=-full -output "$work/report" > /dev/null 2>&1; then
    echo "-args without -case accepted"; exit 1
fi
# A row added by hand to a kept validation.dat (a run made outside Allvalidate) reaches the
# report with -stored, which runs nothing and takes no tutorial's own rows.
echo "elasticBar-uGIMP byHand tipDisplacement m 1 1.01 - 1 - 1 1 1" >> "$work/report/verification_elasticBar/validation.dat"
echo "oedometerPoint-associated-psi10 notKept q Pa 1 2 - 100 - 1 1 1" >> "$work/tutorials/materials/oedometerPoint/validation.dat"
"$work/tutorials/Allvalidate" -stored -output "$work/report" > /dev/null || { echo "-stored failed"; exit 1; }
grep -q "^| elasticBar-uGIMP | byHand |" "$report" || { echo "-stored lost the row added by hand"; exit 1; }
grep -q "| notKept |" "$report" && { echo "-stored took a tutorial's own rows"; exit 1; }
grep -q 'by `tutorials/Allvalidate -stored`' "$report" || { echo "-stored not named in the report"; exit 1; }
if "$work/tutorials/Allvalidate" -stored -case oedometerPoint -output "$work/report" > /dev/null 2>&1; then
    echo "-stored with -case accepted"; exit 1
fi
echo "validation report: $(grep -c '^| ' "$report") table rows"
