#!/bin/bash
# Mass scaling on the seed's vertical anchor (5.2.1: h/B 3, rough, 3 cells across the half
# plate) at the seed's 2 mm/s: the ultimate load factor with the density times 100 within
# 2 % of the unscaled run, in at least 8 times fewer steps (the settle stage's 100 steps
# are a floor in both).
# Usage: massScaling.sh <source dir> <binary dir>
. "$(dirname "$0")/scratchRun.sh" "$@"
cp -r "$source_dir/tutorials/geotechnics/anchors" "$work/case"
cd "$work/case"
entry=vertical:3:3:rough:2
./Allrun -runs "$entry" > plain.txt
cp errors.dat plain.dat
./Allrun -massScaling 100 -runs "$entry" > scaled.txt
cat plain.txt scaled.txt | grep -E '^(kind|vertical)'
# errors.dat: $4 steps, $9 the compared q_u [kPa]
read -r steps0 qu0 <<< "$(awk '!/^#/ { print $4, $9 }' plain.dat)"
read -r steps1 qu1 <<< "$(awk '!/^#/ { print $4, $9 }' errors.dat)"
python3 - "$steps0" "$qu0" "$steps1" "$qu1" <<'PY'
import sys
steps0, qu0, steps1, qu1 = int(sys.argv[1]), float(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4])
change = (qu1 - qu0) / qu0 * 100
print(f"q_u {qu0} kPa unscaled in {steps0} steps, {qu1} kPa scaled 100 times in {steps1} steps: {change:+.2f} %")
ok = abs(change) <= 2 and steps0 >= 8 * steps1
sys.exit(0 if ok else 1)
PY
