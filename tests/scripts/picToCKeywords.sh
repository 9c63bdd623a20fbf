#!/bin/bash
# picToC -keywords TYPE prints the keyword table of the type's header, compiled in at build
# time: every row of mohrCoulomb's and its footnote, the polygon shape's row, "no keywords of
# its own" for a type without, every registered type answers; an unknown type is refused in
# one line naming the valid types, exit 1. The lists without -keywords and -help are as before.
# Usage: picToCKeywords.sh <source dir> <binary dir>
. "$(dirname "$0")/scratchRun.sh" "$@"
fail() { echo "$*"; exit 1; }
out=$(picToC -keywords mohrCoulomb)
[ "$(echo "$out" | head -1)" = "material mohrCoulomb (libmaterials/mohrCoulomb/MohrCoulomb.H)" ] || fail "first line: $out"
for key in rho "E, nu" "K, G" phi psi c sigmaT phiTable psiTable cTable sigmaTTable rhoDisconnected; do
    row=$(grep -E "^// \| $key +\|" "$source_dir/libmaterials/mohrCoulomb/MohrCoulomb.H" | awk -F'|' '{gsub(/^ +| +$/, "", $5); print $5}')
    echo "$out" | grep -qE "^  $key +.* $(printf '%s' "$row" | sed 's/[][()*.^$/]/\\&/g')\$" || fail "mohrCoulomb: no row '$key ... $row' in: $out"
done
echo "$out" | grep -q '^  (\*) with phi = 0 there is no tension cutoff unless sigmaT is given\.$' || fail "mohrCoulomb's footnote: $out"
picToC -keywords polygon | grep -qE '^  points +\(\(x y\) \.\.\.\), at least 3' || fail "polygon: $(picToC -keywords polygon)"
[ "$(picToC -keywords USL | tail -1)" = "  no keywords of its own" ] || fail "USL: $(picToC -keywords USL)"
[ "$(picToC -keywords fixed | grep -c '^[a-zA-Z]')" = 2 ] || fail "fixed: a boundary condition and a driver expected: $(picToC -keywords fixed)"
for type in $(python3 "$source_dir/etc/python/keywordTables.py" types "$source_dir"); do
    picToC -keywords "$type" > /dev/null || fail "picToC -keywords $type failed"
done
status=0
picToC -keywords mohrColoumb > "$work/out" 2> "$work/err" || status=$?
[ "$status" = 1 ] && [ ! -s "$work/out" ] && [ "$(wc -l < "$work/err")" = 1 ] || fail "unknown type: exit $status, $(cat "$work/out" "$work/err")"
grep -q "^Error: picToC -keywords: no keyword table for type 'mohrColoumb'.*; valid types: .*mohrCoulomb" "$work/err" || fail "$(cat "$work/err")"
picToC | grep -q '^material: .*mohrCoulomb' || fail "picToC's list: $(picToC)"
picToC -help | grep -q -- '--keywords' || fail "picToC -help: $(picToC -help)"
echo "picToCKeywords: the tables of $(python3 "$source_dir/etc/python/keywordTables.py" types "$source_dir" | wc -w) types print"
