#!/bin/bash
# Builds the user-plugin example tutorials/plugins/myMaterial OUT OF TREE against the
# installed granularPic CMake package, runs tutorials/plugins/viscoElasticBar with it, and
# checks that the library is loaded, that its type is selectable only when loaded, and
# that the bar's vibration decays as the analytic Kelvin-Voigt rod does.
#
#     pluginExample.sh SOURCE_DIR BINARY_DIR     (BINARY_DIR: a built granular-pic tree)
#
# Environment: CMAKE (the cmake of the main build), CXX (its compiler, for a matching ABI).
set -euo pipefail

fail() { echo "pluginExample: FAIL: $*" >&2; exit 1; }
step() { echo "pluginExample: $*"; }

[ $# -eq 2 ] || fail "usage: $0 SOURCE_DIR BINARY_DIR"
src="$(cd "$1" && pwd)"
bin="$(cd "$2" && pwd)"
cmake="${CMAKE:-cmake}"
generator=()
command -v ninja > /dev/null && generator=(-G Ninja)

tmp="$(mktemp -d "${TMPDIR:-/tmp}/gpic-pluginExample.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT

# Show the tail of a log when a step fails: the test output is all a CI run keeps.
run() {
    local log="$1"; shift
    if ! "$@" > "$log" 2>&1; then
        tail -30 "$log" >&2
        fail "'$*' failed (log above)"
    fi
}

# 1. Install the current build into a fresh prefix: what a user gets from etc/build.
step "installing $bin into $tmp/prefix"
run "$tmp/install.log" "$cmake" --install "$bin" --prefix "$tmp/prefix"
for app in picInit picSolver picToC; do
    [ -x "$tmp/prefix/bin/$app" ] || fail "$app not installed in $tmp/prefix/bin"
done

# 2. Configure and build the plugin against the installed package only (not the build tree).
step "building tutorials/plugins/myMaterial out of tree"
plugin="$tmp/pluginBuild"
run "$tmp/configure.log" "$cmake" -S "$src/tutorials/plugins/myMaterial" -B "$plugin" \
    "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$tmp/prefix"
grep -q "granularPic_DIR:PATH=$tmp/prefix/" "$plugin/CMakeCache.txt" ||
    fail "find_package(granularPic) did not use the installed package in $tmp/prefix"
run "$tmp/build.log" "$cmake" --build "$plugin"
[ -f "$plugin/libmyMaterial.so" ] || fail "no libmyMaterial.so in $plugin"
export LD_LIBRARY_PATH="$plugin:${LD_LIBRARY_PATH:-}"

# 3. picToC lists the new type once the library is loaded.
step "picToC -libs libmyMaterial.so"
toc="$("$tmp/prefix/bin/picToC" -libs libmyMaterial.so)" || fail "picToC -libs libmyMaterial.so failed"
echo "$toc" | grep -E -q '^material: .*\bviscoElastic \[libmyMaterial\.so\]' ||
    fail "picToC -libs libmyMaterial.so does not list viscoElastic marked [libmyMaterial.so]:
$toc"
# Only the library's own types are marked, and every kind is listed.
[ "$(echo "$toc" | grep -o '\[[^]]*\]' | sort -u)" = "[libmyMaterial.so]" ] ||
    fail "picToC marks types other than the library's:
$toc"
for kind in material boundaryCondition contactLaw contactNormals contactAlgorithm shapeFunction \
            updateScheme transfer functionObject shape rigidBodyDriver load stage; do
    echo "$toc" | grep -q "^$kind: " || fail "picToC does not list the kind $kind:
$toc"
done

# 4. Run the case.
step "running tutorials/plugins/viscoElasticBar"
case="$tmp/viscoElasticBar"
mkdir -p "$case"
cp -r "$src/tutorials/plugins/viscoElasticBar/system" "$src/tutorials/plugins/viscoElasticBar/constant" "$case/"
run "$tmp/log.picInit" "$tmp/prefix/bin/picInit" -case "$case"
status=0
"$tmp/prefix/bin/picSolver" -case "$case" > "$tmp/log.picSolver" 2>&1 || status=$?
[ "$status" -eq 0 ] || { tail -30 "$tmp/log.picSolver" >&2; fail "picSolver exited with $status"; }
grep -q "^Loaded library libmyMaterial.so" "$tmp/log.picSolver" ||
    fail "picSolver log has no 'Loaded library libmyMaterial.so'"

# 5. Physics. With nu = 0 and the lateral motion held, the bar is a 1-D Kelvin-Voigt rod,
#        rho u_tt = E u_xx + eta u_xxt,
#    whose first mode (beta = pi/(2L), omega0 = beta c, c = sqrt(E/rho)) decays at
#    gamma = eta beta^2/(2 rho). Starting from v = v0 sin(beta x), u = 0, the centre-of-mass
#    velocity is
#        v_c(t) = A exp(-gamma t) (cos(omega_d t) - gamma/omega_d sin(omega_d t)),
#    A = 2 v0/pi (the elastic amplitude), omega_d = sqrt(omega0^2 - gamma^2).
#    Tolerance 3 % of A: the elastic bar at this resolution (16 cells, bilinear, USL) is
#    within 2 % of the elastic solution (tests/elasticBarTest.C, about 1 % in practice), and
#    the explicit viscous term adds an O(gamma dt) ~ 1e-3 error. A material that ignored
#    eta would miss the decay by 1 - exp(-gamma 15 s) = 45 % of A, far outside 3 %; and
#    the decay itself must exceed 20 % of A, so a case with eta = 0 cannot pass.
#    L and v0 are those of constant/bodies; rho, E, eta are read from constant/materials.
entry() { sed -n "s/^[[:space:]]*$1[[:space:]]\+\([^;[:space:]]*\).*/\1/p" "$2" | head -1; }
materials="$case/constant/materials"
rho="$(entry rho "$materials")"; E="$(entry E "$materials")"; eta="$(entry eta "$materials")"
if [ -z "$rho" ] || [ -z "$E" ] || [ -z "$eta" ]; then
    fail "cannot read rho, E, eta from $materials"
fi
dat="$case/postProcessing/motion/0/bodyMotion.dat"
[ -f "$dat" ] || fail "no $dat"
step "checking $dat against the damped analytic solution (rho $rho, E $E, eta $eta)"
awk -v L=25 -v v0=0.1 -v rho="$rho" -v E="$E" -v eta="$eta" -v tol=0.03 -v tLate=15 '
    BEGIN {
        pi = atan2(0, -1); b = pi / (2 * L); c = sqrt(E / rho)
        g = eta * b * b / (2 * rho); w0 = b * c; wd = sqrt(w0 * w0 - g * g); A = 2 * v0 / pi
    }
    # Column numbers from the last header line: "# time bar:x ... bar:vx ...".
    /^#/ { col = 0; for (i = 2; i <= NF; ++i) if ($i == "bar:vx") col = i - 1; next }
    {
        if (!col) { print "no column bar:vx in the header"; exit 1 }
        t = $1; v = $col; n++
        d = v - A * exp(-g * t) * (cos(wd * t) - g / wd * sin(wd * t))
        if (d < 0) d = -d
        if (d > worst) { worst = d; tWorst = t }
        if (t >= tLate) { a = v < 0 ? -v : v; if (a > late) late = a }
        tEnd = t
    }
    END {
        if (!col) exit 1
        if (n < 100 || tEnd < 20 - 1e-9) { printf "only %d rows up to t = %g (want t = 20)\n", n, tEnd; exit 1 }
        # The last half period [15, 20] s holds the peak at t = 15 s (|cos(omega0 t)| = 1).
        expected = exp(-g * tLate)
        printf "max |v_c - exact| = %.4f A (at t = %g s, tolerance %.2f A)\n", worst / A, tWorst, tol
        printf "amplitude after %g s = %.4f A (damped exact %.4f A, elastic 1 A)\n", tLate, late / A, expected
        bad = 0
        if (worst / A > tol) { print "centre-of-mass velocity departs from the damped solution"; bad = 1 }
        d = late / A - expected; if (d < 0) d = -d
        if (d > tol) { print "the vibration does not decay at the rate eta gives"; bad = 1 }
        # The case must damp visibly: 20 % is ten times the elastic error.
        if (late / A > 0.8) { print "no decay: is eta > 0 in constant/materials?"; bad = 1 }
        exit bad
    }' "$dat" || fail "physics check on $dat (see above)"

# 6. Without the library the type is unknown: exit 1 and a one-line error naming the
#    valid choices. The library stays on LD_LIBRARY_PATH: only `libs` must load it.
step "running the case without libs (...): expecting a clean input error"
nolib="$tmp/noLib"
mkdir -p "$nolib"
cp -r "$src/tutorials/plugins/viscoElasticBar/system" "$src/tutorials/plugins/viscoElasticBar/constant" "$nolib/"
sed -i '/^[[:space:]]*libs[[:space:]]/d' "$nolib/system/controlDict"
status=0
"$tmp/prefix/bin/picInit" -case "$nolib" > "$tmp/noLib.out" 2> "$tmp/noLib.err" || status=$?
[ "$status" -eq 1 ] || { cat "$tmp/noLib.err" >&2; fail "picInit without the library exited with $status, want 1"; }
[ "$(wc -l < "$tmp/noLib.err")" -eq 1 ] || { cat "$tmp/noLib.err" >&2; fail "error is not one line"; }
grep -q "unknown material type 'viscoElastic'.*valid choices: .*linearElastic" "$tmp/noLib.err" ||
    fail "error does not name the type and the valid choices: $(cat "$tmp/noLib.err")"
! grep -q "valid choices: .*viscoElastic" "$tmp/noLib.err" ||
    fail "viscoElastic was selectable without its library: $(cat "$tmp/noLib.err")"

step "PASS"
