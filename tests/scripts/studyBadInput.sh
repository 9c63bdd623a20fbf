#!/bin/bash
# picStudy refuses a bad studyDict before it writes a case: one line naming the file, the
# line and the keyword (and the valid choices where there is a choice), exit status 1.
# Usage: studyBadInput.sh <source dir> <binary dir>
. "$(dirname "$0")/scratchRun.sh" "$@"
. "$(dirname "$0")/studyCase.sh"
cd "$work/case"
cp system/studyDict studyDict.good
failures=0
# refused <sed edit> <keyword> <words the message must hold>: the error names the edited line
refused() {
    local edit=$1 keyword=$2 words=$3 line code=0
    cp studyDict.good system/studyDict
    sed -i "$edit" system/studyDict
    cmp -s studyDict.good system/studyDict && { echo "edit '$edit' changed nothing"; failures=$((failures + 1)); return; }
    line=$(diff studyDict.good system/studyDict | head -1 | grep -oE '^[0-9]+' || true)   # the edited line
    picStudy -dryRun > out.txt 2> err.txt || code=$?
    if [ "$code" != 1 ] || [ "$(wc -l < err.txt)" != 1 ] || ! grep -q "^Error: system/studyDict:$line: keyword '$keyword'" err.txt \
        || ! grep -q -- "$words" err.txt || [ -e studies/four ]; then
        echo "not refused as expected ($edit: exit $code, line $line):"; cat err.txt
        failures=$((failures + 1))
    else
        echo "refused: $(cat err.txt)"
    fi
}
refused 's/^executor .*/executor    cluster;/' executor 'valid choices: local, slurm'
refused 's/file constant\/contactProperties;/file constant\/contact;/' file 'valid choices: .*constant/contactProperties'
refused 's/entry mu;/entry friction;/' entry 'valid choices: law, normals, mu'
refused 's/entry blade\/shape\/min;/entry blade\/shape;/' entry 'is a sub-dictionary'
refused 's/step 0.05;/step -0.05;/' step 'never reaches end'
refused 's/step 0.05;/count 1;/' count 'cannot span'
refused 's/{0.4 - depth}) (0.3 {0.4 - depth})/{0.4 - depht}) (0.3 {0.4 - depth})/' value "unknown name 'depht'"
refused 's/value "(0.3 {0.4 - depth})"/value "(0.3 {__import__(1)})"/' value 'unknown function'
refused 's/functionObject forces; column front:Fx/functionObject force; column front:Fx/' functionObject 'valid choices: forces'
refused 's/statistic max;/statistic median;/' statistic 'valid choices: mean, max, min, at, last'
refused 's/^design .*/design random;/' design 'valid choices: factorial, latinHypercube'
refused 's/file constant\/contactProperties; entry mu;/file constant\/bodies; entry blade\/shape\/min;/' entry 'set twice (also by depth)'
[ $failures = 0 ] || { echo "$failures inputs not refused as expected"; exit 1; }
cp studyDict.good system/studyDict
code=0; picStudy -executor pbs -dryRun 2> err.txt || code=$?
[ $code = 1 ] && grep -q "valid choices: local, slurm" err.txt || { echo "-executor pbs not refused"; exit 1; }
echo "every bad input refused with its file, line and keyword"
