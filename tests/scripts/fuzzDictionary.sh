#!/bin/bash
# Builds the dictionary parser's libFuzzer target (tests/fuzz/dictionaryFuzz.C) with clang,
# AddressSanitizer and UndefinedBehaviorSanitizer, and runs it from a seed corpus of every
# dictionary in tutorials/ and bench/cases/. No crash, no hang (10 s per input), no sanitizer
# report, every refusal a one-line InputError.
#
#     fuzzDictionary.sh SOURCE_DIR [RUNS]     RUNS: inputs to try (default 20000, seconds);
#                                              e.g. 5000000 for a developer's long run,
#                                              or -max_total_time=3600 style options after it
set -euo pipefail

fail() { echo "fuzzDictionary: FAIL: $*" >&2; exit 1; }
[ $# -ge 1 ] || fail "usage: $0 SOURCE_DIR [RUNS] [libFuzzer options]"
src="$(cd "$1" && pwd)"
runs="${2:-20000}"
shift $(( $# >= 2 ? 2 : 1 ))
cxx="${CLANGXX:-clang++}"
command -v "$cxx" > /dev/null || fail "$cxx not found (etc/installDependencies -tests installs clang)"

work="$(mktemp -d "${TMPDIR:-/tmp}/gpic-fuzzDictionary.XXXXXX")"
trap 'rm -rf "$work"' EXIT

# The parser and what it needs, compiled with the fuzzer's coverage (libpic is built by g++).
"$cxx" -std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
    -I"$src/libpic" -I/usr/include/eigen3 \
    "$src/tests/fuzz/dictionaryFuzz.C" "$src"/libpic/dictionary/*.C "$src/libpic/core/error.C" \
    -o "$work/dictionaryFuzz" > "$work/build.log" 2>&1 || { tail -30 "$work/build.log" >&2; fail "build"; }

# Seeds: the project's own dictionaries (the grammar as users write it).
mkdir -p "$work/corpus"
k=0
while IFS= read -r -d '' f; do
    cp "$f" "$work/corpus/seed$k"
    k=$((k + 1))
done < <(find "$src/tutorials" "$src/bench/cases" -type f \( -path '*/system/*' -o -path '*/constant/*' \) \
              -size -64k -print0)
[ "$k" -gt 10 ] || fail "only $k seed dictionaries found"

echo "fuzzDictionary: $k seeds, $runs inputs"
# Warnings of duplicate keywords go to stderr: close the target's stdout only.
if ! "$work/dictionaryFuzz" -runs="$runs" -timeout=10 -rss_limit_mb=2048 -max_len=4096 -seed=1 \
        -artifact_prefix="$work/" "$@" "$work/corpus" > "$work/fuzz.log" 2>&1; then
    grep -v "^Warning:" "$work/fuzz.log" | tail -40 >&2
    for a in "$work"/crash-* "$work"/timeout-* "$work"/leak-* "$work"/oom-*; do
        [ -f "$a" ] || continue
        mkdir -p "${TMPDIR:-/tmp}/gpic-fuzz-findings"
        cp "$a" "${TMPDIR:-/tmp}/gpic-fuzz-findings/"
        echo "finding kept: ${TMPDIR:-/tmp}/gpic-fuzz-findings/$(basename "$a")" >&2
    done
    fail "the fuzzer found an input the parser does not handle (above)"
fi
grep -E "^Done [0-9]+ runs" "$work/fuzz.log" || tail -3 "$work/fuzz.log"
echo "fuzzDictionary: PASS"
