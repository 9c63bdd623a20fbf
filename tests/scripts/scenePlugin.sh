#!/bin/bash
# Builds tests/support/scenePlugin (a contact law `freeSlip`, a rigid-body driver `shaker` and
# a function object `gridMomentum` hooked after particles-to-grid and after the grid update)
# OUT OF TREE against the installed granularPic package, as a user would, and runs without a
# file of the project touched a scene that uses the law and the driver, a plate shaken along
# x1 under an elastic block resting on it, and one for the function object (below).
#   - The driver: the plate's displacement (forces' dx) is A sin(omega t) to 1e-9 m.
#   - The law: without friction the plate cannot drag the block, so the block's x1 velocity
#     stays below 5 % of the plate's peak A omega; the same scene with the built-in
#     coulombFriction, mu 1 (the plate's peak acceleration A omega^2 is 0.5 g), drags it
#     along above half of A omega, so the check tells the laws apart.
#
#     scenePlugin.sh SOURCE_DIR BINARY_DIR     (BINARY_DIR: a built granular-pic tree)
#
# Environment: CMAKE (the cmake of the main build), CXX (its compiler, for a matching ABI).
set -euo pipefail

fail() { echo "scenePlugin: FAIL: $*" >&2; exit 1; }
step() { echo "scenePlugin: $*"; }

[ $# -eq 2 ] || fail "usage: $0 SOURCE_DIR BINARY_DIR"
src="$(cd "$1" && pwd)"
bin="$(cd "$2" && pwd)"
cmake="${CMAKE:-cmake}"
generator=()
command -v ninja > /dev/null && generator=(-G Ninja)
tmp="$(mktemp -d "${TMPDIR:-/tmp}/gpic-scenePlugin.XXXXXX")"
[ -n "${KEEP:-}" ] || trap 'rm -rf "$tmp"' EXIT
run() {
    local log="$1"; shift
    if ! "$@" > "$log" 2>&1; then tail -30 "$log" >&2; fail "'$*' failed (log above)"; fi
}

step "installing $bin into $tmp/prefix, building the plugin against it"
run "$tmp/install.log" "$cmake" --install "$bin" --prefix "$tmp/prefix"
run "$tmp/configure.log" "$cmake" -S "$src/tests/support/scenePlugin" -B "$tmp/build" "${generator[@]}" \
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$tmp/prefix"
run "$tmp/build.log" "$cmake" --build "$tmp/build"
[ -f "$tmp/build/libscenePlugin.so" ] || fail "no libscenePlugin.so"
export LD_LIBRARY_PATH="$tmp/build:$tmp/prefix/lib:${LD_LIBRARY_PATH:-}"

toc="$("$tmp/prefix/bin/picToC" -libs libscenePlugin.so)" || fail "picToC -libs libscenePlugin.so"
echo "$toc" | grep -q '^contactLaw: .*freeSlip \[libscenePlugin\.so\]' || fail "picToC lacks freeSlip: $toc"
echo "$toc" | grep -q '^rigidBodyDriver: .*shaker \[libscenePlugin\.so\]' || fail "picToC lacks shaker: $toc"

# Both scenes: 40 x 20 cells of 5 mm, every side free.
freeGrid() {
    cat > "$1/constant/grid" <<DICT
origin (0 0); cellSize 0.005; nCells (40 20);
boundaries { left { type free; } right { type free; } bottom { type free; } top { type free; } }
DICT
}

# The scene: 40 x 20 cells of 5 mm; the plate 160 x 10 mm shaken 5 mm at 5 Hz for 0.4 s.
A=0.005; omega=31.41592653589793
scene() {
    local case="$1" law="$2"
    mkdir -p "$case/system" "$case/constant"
    cat > "$case/system/controlDict" <<DICT
libs ("libscenePlugin.so");
endTime 0.4; deltaT 1; adjustTimeStep yes; maxCourant 0.4; writeControl runTime; writeInterval 0.4;
functions
{
    plate { type forces; bodies (plate); writeInterval 20; }
    motion { type bodyMotion; writeInterval 20; }
}
DICT
    # USL with uGIMP: bilinear cells fail this scene either way, stopped by the stability
    # guard (MUSL without `correctRemapped yes`: the block resting on the plate gains energy,
    # doc/contact.md; USL: the block's corner dragged with friction).
    echo "updateScheme USL; shapeFunction uGIMP;" > "$case/system/mpmSchemes"
    freeGrid "$case"
    cat > "$case/constant/materials" <<DICT
gel   { type linearElastic; rho 1000; E 1e6; nu 0.3; }
steel { type linearElastic; rho 7800; E 2e8; nu 0.3; }
DICT
    cat > "$case/constant/bodies" <<DICT
plate { material steel; shape { type rectangle; min (0.02 0.01); max (0.18 0.02); } particlesPerCell 2; }
block { material gel;   shape { type rectangle; min (0.07 0.02); max (0.13 0.05); } particlesPerCell 2;
        initialStress { type geostatic; K0 0.43; } }   // at rest under its weight: nu/(1 - nu)
DICT
    echo "plate { type shaker; amplitude $A; omega $omega; }" > "$case/constant/rigidBodies"
    echo "value (0 -9.81);" > "$case/constant/g"
    echo "law $law; mu 1; normals rigidSurface;" > "$case/constant/contactProperties"
    run "$case.picInit.log" "$tmp/prefix/bin/picInit" -case "$case"
    run "$case.picSolver.log" "$tmp/prefix/bin/picSolver" -case "$case"
}

# Largest |block:vx| over the run, in units of A omega; and the worst |dx - A sin(omega t)|.
peakBlockSpeed() {
    awk -v ref="$(awk -v a=$A -v w=$omega 'BEGIN { print a * w }')" '
        /^#/ { for (i = 2; i <= NF; ++i) if ($i == "block:vx") col = i - 1; next }
        { v = $col < 0 ? -$col : $col; if (v > m) m = v; n++ }
        END { if (!col || n < 50) { print "bad"; exit 1 } printf "%.4f\n", m / ref }' "$1"
}

step "freeSlip: the plate shaken under the block"
scene "$tmp/freeSlip" freeSlip
grep -q "^Loaded library libscenePlugin.so" "$tmp/freeSlip.picSolver.log" || fail "libscenePlugin.so not loaded"
grep -q "Contact pass: 2 bodies" "$tmp/freeSlip.picSolver.log" || fail "no contact pass with freeSlip"
awk -v a=$A -v w=$omega '
    /^#/ { for (i = 2; i <= NF; ++i) if ($i == "plate:dx") col = i - 1; next }
    { d = $col - a * sin(w * $1); if (d < 0) d = -d; if (d > worst) worst = d; n++ }
    END { if (!col || n < 50) { print "no plate:dx rows"; exit 1 }
          printf "shaker: max |dx - A sin(omega t)| = %.3g m over %d rows\n", worst, n; exit worst > 1e-9 }' \
    "$tmp/freeSlip/postProcessing/plate/0/forces.dat" || fail "the plate does not follow A sin(omega t)"
free="$(peakBlockSpeed "$tmp/freeSlip/postProcessing/motion/0/bodyMotion.dat")" || fail "no block:vx rows"
step "freeSlip: block's peak |vx| = $free A omega (limit 0.05)"
awk -v f="$free" 'BEGIN { exit !(f < 0.05) }' || fail "freeSlip let the plate drag the block"

step "coulombFriction, mu 1: the same scene"
scene "$tmp/friction" coulombFriction
stuck="$(peakBlockSpeed "$tmp/friction/postProcessing/motion/0/bodyMotion.dat")" || fail "no block:vx rows"
step "coulombFriction: block's peak |vx| = $stuck A omega (must exceed 0.5)"
awk -v f="$stuck" 'BEGIN { exit !(f > 0.5) }' || fail "friction did not drag the block: the check cannot tell the laws apart"
# The function object hooked inside the step: a block falling freely (stress-free, no side
# reached) has grid momentum -M g t_n after particles-to-grid and -M g t_(n+1) after the grid
# update; the check tells the two points apart (they differ by M g dt, 1/100 of the value at
# the end), and fails if the hooks are not called at all.
step "gridMomentum: a block falling freely, the grid's momentum at two points of the step"
fall="$tmp/fall"
mkdir -p "$fall/system" "$fall/constant"
cat > "$fall/system/controlDict" <<DICT
libs ("libscenePlugin.so");
endTime 0.05; deltaT 5e-5; adjustTimeStep no; writeControl runTime; writeInterval 0.05;
functions { grid { type gridMomentum; writeInterval 10; } }
DICT
echo "updateScheme MUSL; shapeFunction bilinear; transfer FLIP;" > "$fall/system/mpmSchemes"
freeGrid "$fall"
echo "gel { type linearElastic; rho 1000; E 1e6; nu 0.3; }" > "$fall/constant/materials"
echo "block { material gel; shape { type rectangle; min (0.07 0.05); max (0.13 0.08); } particlesPerCell 2; }" \
    > "$fall/constant/bodies"
echo "value (0 -9.81);" > "$fall/constant/g"
run "$fall.picInit.log" "$tmp/prefix/bin/picInit" -case "$fall"
run "$fall.picSolver.log" "$tmp/prefix/bin/picSolver" -case "$fall"
awk '
    /^#/ || $1 == 0 { next }   # the start row: no step taken yet
    { g = 9.81; ref = $3 * g * $1
      before = $4 + $3 * g * $2; if (before < 0) before = -before
      after = $5 + $3 * g * $1; if (after < 0) after = -after
      if (before > worstB) worstB = before / ref; if (after > worstA) worstA = after / ref
      if (!($2 < $1)) late = 1; n++ }
    END { if (n < 50) { print "only " n " gridMomentum rows"; exit 1 }
          printf "gridMomentum: %d rows, |p_y + M g t_n| / M g t %.2g before, |p_y + M g t_(n+1)| / M g t %.2g after the update\n", n, worstB, worstA
          exit late || worstB > 1e-9 || worstA > 1e-9 }' \
    "$fall/postProcessing/grid/0/gridMomentum.dat" || fail "the hooked function object did not see the grid at its points"
# A parallel run refuses a function object whose type does not say it serves parallel runs
# (gridMomentum reads the grid of its own rank alone), in one line, before any step.
if ldd "$(ls "$tmp"/prefix/lib*/libpic.so* | head -1)" | grep -q libmpi && command -v mpirun > /dev/null; then
    step "gridMomentum refused by a parallel run"
    printf 'numberOfSubdomains 2;\nmethod simple;\nsimpleCoeffs { n (2 1); }\n' > "$fall/system/decomposeParDict"
    rm -rf "$fall"/processor* && run "$fall.picDecompose.log" "$tmp/prefix/bin/picDecompose" -case "$fall" -time 0
    if out=$(mpirun --oversubscribe --allow-run-as-root -np 2 "$tmp/prefix/bin/picSolver" -case "$fall" -parallel 2>&1); then
        fail "a parallel run took gridMomentum"
    fi
    grep -q "function object grid: its type does not say it serves parallel runs" <<< "$out" || fail "message: $out"
fi
step "PASS"
