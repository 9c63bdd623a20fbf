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
for scene in $(ls "$source_dir/bench/cases"); do
    grep -qE "^\| $scene \| 1 \| [0-9]" "$work/results.md" || { echo "no result for scene $scene"; exit 1; }
done
! grep -q "failed" "$work/results.md" || { echo "a scene failed"; exit 1; }
echo "bench/run -quick: $(ls "$source_dir/bench/cases" | wc -w) scenes"
