#!/bin/bash
# A four-case study run by the local executor and as a Slurm job array on a one-node
# cluster started here (slurmLocal.sh) gives the same results.csv but for the wall time;
# so does an array submitted with -noWait and followed by a second picStudy.
# Usage: studyLocalSlurm.sh <source dir> <binary dir>
. "$(dirname "$0")/scratchRun.sh" "$@"
. "$(dirname "$0")/studyCase.sh"
. "$(dirname "$0")/slurmLocal.sh" "$work"
trap 'slurm_stop; rm -rf "$work"' EXIT
cd "$work/case"
picStudy -quiet -output "$work/local"
picStudy -quiet -output "$work/slurm" -executor slurm
local_csv=$work/local/four/results.csv slurm_csv=$work/slurm/four/results.csv
cat "$local_csv" "$slurm_csv"
# the Slurm run went through Slurm: its job, and each task's output file
[ -s "$work/slurm/four/slurm/job" ] || { echo "no Slurm job recorded"; exit 1; }
outputs=$(ls "$work"/slurm/four/slurm/*_*.out | wc -l)
[ "$outputs" = 4 ] || { echo "expected 4 Slurm task outputs, found $outputs"; exit 1; }
[ ! -e "$work/local/four/slurm" ] || { echo "the local run went through Slurm"; exit 1; }
rows=$(grep -c ',finished,$' "$local_csv" || true)
[ "$rows" = 4 ] || { echo "expected 4 finished cases, found $rows"; exit 1; }
# every result a number in both
python3 - "$local_csv" <<'PY'
import csv, sys
for row in csv.DictReader(open(sys.argv[1])):
    for name in ('draftForce', 'frontForce', 'liftAtEnd', 'steps', 'wallTime_s'):
        float(row[name])
PY
diff <(without_wall_time "$local_csv") <(without_wall_time "$slurm_csv") \
    || { echo "local and Slurm results differ"; exit 1; }
# Submitted without waiting, then picStudy again at once: it follows the queued array
# instead of submitting the cases a second time, and collects the same rows.
picStudy -quiet -output "$work/queued" -executor slurm -noWait > noWait.txt
picStudy -quiet -output "$work/queued" -executor slurm > follow.txt
cat noWait.txt follow.txt
grep -q "still queued: following it" follow.txt || { echo "the second call did not follow the queued array"; exit 1; }
[ "$(ls "$work"/queued/four/slurm/*_*.out | wc -l)" = 4 ] || { echo "cases ran twice"; exit 1; }
diff <(without_wall_time "$local_csv") <(without_wall_time "$work/queued/four/results.csv") \
    || { echo "the followed array's results differ"; exit 1; }
echo "local and Slurm: the same 4 rows but for the wall time"
