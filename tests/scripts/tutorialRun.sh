#!/bin/bash
# Runs a tutorial's Allrun (its coarse ladder) on a copy and checks what it promises the
# user: a table of resolution, particles, steps, wall time and error, and the PNG plots.
# Usage: tutorialRun.sh <source dir> <binary dir> <tutorial path> <png>...
set -euo pipefail
source_dir=$1 binary_dir=$2 tutorial=$3
shift 3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export GPIC_DIR=$source_dir
export PATH=$binary_dir/bin:$PATH
cp -r "$source_dir/tutorials/$tutorial" "$work/case"
(cd "$work/case" && ./Allclean && ./Allrun) | tee "$work/out"
grep -q "wall s" "$work/out" || { echo "no error-against-run-time table"; exit 1; }
rows=$(grep -cE '^[A-Za-z][A-Za-z0-9]* +[0-9e.+-]+ +[0-9]+ +[0-9]+ ' "$work/out" || true)
[ "$rows" -ge 2 ] || { echo "expected at least 2 ladder rows, found $rows"; exit 1; }
for png in "$@"; do
    [ -s "$work/case/$png" ] || { echo "missing plot $png"; exit 1; }
done
echo "tutorial $tutorial: $rows ladder rows, plots $*"
