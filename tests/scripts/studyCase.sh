# Sourced by the picStudy tests after scratchRun.sh: $work/case, the bladeDepthFriction
# tutorial's base case pushed for 2 mm only (a few seconds a case), with a four-case study
# (two depths by two blade frictions) whose results need only those 2 mm.
cp -r "$source_dir/tutorials/studies/bladeDepthFriction" "$work/case"
. "$source_dir/etc/RunFunctions"
setKeyword "$work/case/system/controlDict" endTime 0.04
setKeyword "$work/case/system/controlDict" writeInterval 0.02
cat > "$work/case/system/studyDict" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; location "system"; object studyDict; }

name        four;
design      factorial;
parameters
{
    depth
    {
        range   { start 0.15; end 0.2; step 0.05; }
        set
        {
            sand    { file constant/bodies; entry soil/shape/points;
                      value "((0 0) (1 0) (1 0.4) (0.325 0.4) (0.325 {0.4 - depth}) (0.3 {0.4 - depth}) (0.3 0.4) (0 0.4))"; }
            blade   { file constant/bodies; entry blade/shape/min; value "(0.3 {0.4 - depth})"; }
            front   { file system/controlDict; entry functions/forces/faces/front/from; value "(0.325 {0.4 - depth})"; }
        }
    }
    mu          { values (0.1 0.3); file constant/contactProperties; entry mu; }
}
results
{
    draftForce  { functionObject forces; column blade:Fx; scale -1; statistic mean; over blade:dx; from 0.0005; to 0.002; }
    frontForce  { functionObject forces; column front:Fx; scale -1; statistic max; }
    liftAtEnd   { functionObject forces; column blade:Fy; statistic at; time 0.03; }
}
executor    local;
local       { parallel 2; }
slurm       { partition debug; timeLimit 00:10:00; coresPerTask 1; pollInterval 1; }
DICT
# results.csv without its wall-time column (the one that differs between runs)
without_wall_time() {
    python3 -c 'import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
k = rows[0].index("wallTime_s")
for row in rows:
    print(",".join(row[:k] + row[k + 1:]))' "$1"
}
