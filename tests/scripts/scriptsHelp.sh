#!/bin/bash
# Every script a user runs answers -help, --help and -h alike: exit 0, its usage on stdout,
# nothing else done (each runs from a scratch copy, so one that ignored -help would clean or
# run only the copy). A tutorial's help names every option its Allrun takes, each of them
# passes its check of options, and an option it does not know stops it in one line, exit 1,
# as it does the top-level Allrun, Alltest, Allclean and etc/build.
# Usage: scriptsHelp.sh <source dir> <binary dir>
. "$(dirname "$0")/scratchRun.sh" "$@"
cd "$source_dir"
scripts="Allrun Alltest Allclean etc/build etc/installDependencies bench/run bench/parallel tutorials/Allvalidate
         $(ls tutorials/*/*/Allrun tutorials/*/*/Allclean)"
failed=0
check() {  # check <name> <command...>: the three spellings of help
    local name=$1; shift
    for flag in -help --help -h; do
        local out status=0
        out=$("$@" "$flag" 2> "$work/stderr" < /dev/null) || status=$?
        if [ "$status" -ne 0 ] || [ -z "$out" ] || [ -s "$work/stderr" ]; then
            echo "$name $flag: exit $status, $(echo "$out" | wc -l) lines of usage, stderr: $(head -c 200 "$work/stderr")"
            failed=1
        fi
    done
    echo "$out" > "$work/usage"
}
for s in $scripts; do
    mkdir -p "$work/copy/$(dirname "$s")"
    cp "$s" "$work/copy/$s"
    # the Python scripts find their modules through GPIC_DIR, the shell ones need nothing else
    check "$s" "$work/copy/$s"
    case "$s" in tutorials/*/*/Allrun)
        # the options it tests for ("$1" = -full, case labels -full) | -runs) ...) are in its help
        # and pass its check (etc/RunFunctions refuseUnknownOptions), with nothing run
        for option in $(grep -oE '"\$[1a-z]+" = "?-[A-Za-z]+|^ *-[A-Za-z]+( \| -[A-Za-z]+)*\)' "$s" |
                        grep -oE '\-[A-Za-z]+' | grep -vxE -- '-h|-help' | sort -u); do
            grep -q -- "$option" "$work/usage" || { echo "$s: option $option is not in its -help"; failed=1; }
            (cd "$work/copy/$(dirname "$s")" &&
             bash -c '. "$GPIC_DIR/etc/RunFunctions"; refuseUnknownOptions "$@"' Allrun "$option" 1) ||
                { echo "$s: its own option $option is refused"; failed=1; }
        done ;;
    esac
    case "$s" in Allrun | Alltest | Allclean | etc/build | tutorials/*/*/Allrun)
        status=0
        "$work/copy/$s" -noSuchOption > "$work/stdout" 2> "$work/stderr" < /dev/null || status=$?
        if [ "$status" -ne 1 ] || [ -s "$work/stdout" ] || [ "$(wc -l < "$work/stderr")" -ne 1 ] ||
           ! grep -q "^Error: [A-Za-z]*: unknown option '-noSuchOption'" "$work/stderr"; then
            echo "$s -noSuchOption: exit $status, stdout $(head -c 100 "$work/stdout"), stderr $(head -c 300 "$work/stderr")"
            failed=1
        fi ;;
    esac
done
check picStudy "$binary_dir/bin/picStudy"
[ "$failed" -eq 0 ] && echo "scriptsHelp: $(echo $scripts | wc -w) scripts and picStudy answer -help, --help and -h;" \
                           "the Allrun, Alltest, Allclean and etc/build refuse an unknown option"
exit "$failed"
