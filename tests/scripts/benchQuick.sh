#!/bin/bash
# bench/run -quick on the build tree: every scene must run, and results.md must carry the
# throughput, per-pass and target tables (figures are not checked: no timing assertions).
# Usage: benchQuick.sh <source dir> <binary dir>
set -euo pipefail
source_dir=$1 binary_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$source_dir/bench/run" -quick -threads 1 -platform "$binary_dir" -output "$work/results.md" \
    | tee "$work/out"
for section in "## Machine" "## Throughput" "## Time per pass" "## Targets"; do
    grep -q "^$section" "$work/results.md" || { echo "results.md lacks '$section'"; exit 1; }
done
scenes=$(ls "$source_dir/bench/cases" | grep -v '3D$')   # the 3D ones: bench/run -threeD below
for scene in $scenes; do
    grep -qE "^\| $scene \| 1 \| [0-9]" "$work/results.md" || { echo "no result for scene $scene"; exit 1; }
done
! grep -q "failed" "$work/results.md" || { echo "a scene failed"; exit 1; }
echo "bench/run -quick: $(echo $scenes | wc -w) scenes"
# The 3D engine's scenes and the cost of 3D contact, where the build has 3D.
if [ -x "$binary_dir/bin/benchThreeD" ]; then
    python3 "$source_dir/bench/run" -quick -threeD -threads 1 -platform "$binary_dir" -output "$work/results-3d.md"
    for section in "## Time per pass" "## The cost of contact in 3D"; do
        grep -q "^$section" "$work/results-3d.md" || { echo "results-3d.md lacks '$section'"; exit 1; }
    done
    grep -qE "^\| 1 \| [0-9]+ \| 20 \|" "$work/results-3d.md" || { echo "no 3D contact row"; exit 1; }
    echo "bench/run -quick -threeD: column, block and the 3D blade with and without contact"
fi
