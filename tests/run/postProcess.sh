#!/usr/bin/env bash
# mpmFoam -postProcess (issue 32): the function objects of controlDict evaluated on the written
# times, without stepping, write the rows the live run wrote at those times.
#  - tests/cases/restartBodies2D (sand, a disk and a box) run with a fixed step, writing every
#    50 steps, its function objects (energy, rigidBodyState, centreOfMass, intrusionDepth,
#    probes, isolatedPoints; contactGap, loadCell) every 50 steps too: after deleting
#    postProcessing/, -postProcess writes files byte-identical to the live ones (the same
#    header, the same rows at the written times 0 … 0.02); the step-only types are skipped
#    with one line each and write nothing; run over the live files it replaces them and says
#    so;
#  - -func (only that one), -time 0.005:0.015 (postProcessing/<name>/0.005/ with the live rows
#    at those times), -time 0.02,0.01, -latestTime;
#  - refused with exit 1 and a message: an unknown -func (listing the valid names), -func of a
#    step-only type (saying why), a -time that is not written, -func without -postProcess,
#    -time with -latestTime, a decomposed case without reconstructed times (reconstructPar);
#  - a time-varying g (sinusoidal): energy's gravitational column is the work read from
#    <time>/uniform/accelerationWork, identical too;
#  - -help lists the options.
set -euo pipefail
. "$(dirname "$0")/../tools/scriptTest.sh"
export OMP_NUM_THREADS=1
ok() { echo "ok: $*"; }
bad() {
    echo "FAIL: $*"
    fail=1
}
# post CASE ARGS...: mpmFoam -postProcess, its log in CASE/log.post; stop on failure.
post() {
    local c=$1
    shift
    "$solver" -case "$c" -postProcess "$@" >"$c/log.post" 2>&1 ||
        { cat "$c/log.post"; echo "FAIL: mpmFoam -postProcess $*"; exit 1; }
}
# refused CASE TEXT ARGS...: mpmFoam ARGS exits 1 and its standard error contains TEXT.
refused() {
    local c=$1 text=$2 rc=0
    shift 2
    "$solver" -case "$c" "$@" >"$work/out" 2>"$work/err" || rc=$?
    if [ "$rc" -eq 1 ] && grep -qF -- "$text" "$work/err"; then
        ok "refused: $* ($text)"
    else
        cat "$work/out" "$work/err"
        bad "$* (exit $rc, expected 1 and '$text')"
    fi
}
# rows FILE FIRST LAST: the # lines of FILE and its data rows FIRST..LAST (from 1).
rows() { grep '^#' "$1"; grep -v '^#' "$1" | sed -n "$2,$3p"; }

"$solver" -help >"$work/help" 2>&1
for o in "-postProcess" "-func <name>" "-time <list>" "-latestTime"; do
    grep -qF -- "  $o" "$work/help" || bad "-help does not list $o"
done

# ---- the live run
c=$work/case
copy restartBodies2D "$c"
cat >"$c/system/controlDict" <<'EOF'
application: mpmFoam
endTime: 0.02
deltaT: 1.0e-4
writeControl: timeStep
writeInterval: 50
functions:
  energy: {type: energy, writeInterval: 50}
  bodies: {type: rigidBodyState, writeInterval: 50}
  com: {type: centreOfMass, writeInterval: 50}
  depth: {type: intrusionDepth, body: disk, writeInterval: 50}
  probe:
    type: probes
    fields: [pressure, velocity, stress, phaseDensity]
    probeLocations: [[0.2, 0.1], [0.1, 0.05]]
    writeInterval: 50
  isolated: {type: isolatedPoints, writeInterval: 50}
  gap: {type: contactGap}
  load: {type: loadCell, face: yMin, writeInterval: 50}
EOF
run "$c" 1
[ "$(writes "$c" | tr '\n' ' ')" = "0 0.005 0.01 0.015 0.02 " ] || bad "times written: $(writes "$c")"
cp -r "$c/postProcessing" "$work/live"
state="energy bodies com depth probe isolated"
for f in $state; do
    [ "$(grep -vc '^#' "$work/live/$f/0/$f.dat")" -eq 5 ] || bad "live $f: not 5 rows"
done

# Over the live files: replaced, and said so.
post "$c"
grep -q "^Replacing postProcessing/energy/0/energy.dat" "$c/log.post" || bad "no 'Replacing' line"
rm -rf "$c/postProcessing"
post "$c"
same=1
for f in $state; do
    cmp -s "$work/live/$f/0/$f.dat" "$c/postProcessing/$f/0/$f.dat" || {
        diff "$work/live/$f/0/$f.dat" "$c/postProcessing/$f/0/$f.dat" | head -6
        same=0
        bad "$f: the post-processed rows differ from the live ones"
    }
done
[ $same = 1 ] && ok "-postProcess: $state identical to the live run (5 times)"
grep -q "^gap (contactGap): needs the time step's contact search" "$c/log.post" &&
    grep -q "^load (loadCell): needs every time step's grid update" "$c/log.post" &&
    [ ! -e "$c/postProcessing/gap" ] && [ ! -e "$c/postProcessing/load" ] &&
    ok "contactGap and loadCell skipped with one line each" || bad "step-only function objects"
grep -q "^Replacing" "$c/log.post" && bad "'Replacing' without a file to replace"

# -func, -time, -latestTime.
rm -rf "$c/postProcessing"
post "$c" -func energy
[ "$(ls "$c/postProcessing")" = energy ] && cmp -s "$work/live/energy/0/energy.dat" \
    "$c/postProcessing/energy/0/energy.dat" && ok "-func energy" || bad "-func energy"
rm -rf "$c/postProcessing"
post "$c" -time 0.005:0.015
same=1
for f in $state; do
    cmp -s <(rows "$work/live/$f/0/$f.dat" 2 4) "$c/postProcessing/$f/0.005/$f.dat" ||
        { same=0; bad "-time 0.005:0.015: $f"; }
done
[ $same = 1 ] && ok "-time 0.005:0.015: the live rows 0.005, 0.01, 0.015 in postProcessing/*/0.005/"
post "$c" -time 0.02,0.01 -func bodies
cmp -s <(rows "$work/live/bodies/0/bodies.dat" 3 3; grep -v '^#' "$work/live/bodies/0/bodies.dat" |
    sed -n 5p) "$c/postProcessing/bodies/0.01/bodies.dat" && ok "-time 0.02,0.01" || bad "-time 0.02,0.01"
post "$c" -latestTime
same=1
for f in $state; do
    cmp -s <(rows "$work/live/$f/0/$f.dat" 5 5) "$c/postProcessing/$f/0.02/$f.dat" ||
        { same=0; bad "-latestTime: $f"; }
done
[ $same = 1 ] && ok "-latestTime: the live row at 0.02 in postProcessing/*/0.02/"

# Refusals.
refused "$c" "-func nosuch: no function object 'nosuch' in the functions of system/controlDict (valid: energy, bodies, com, depth, probe, isolated)" \
    -postProcess -func nosuch
refused "$c" "-func gap: gap (contactGap) needs the time step's contact search" -postProcess -func gap
refused "$c" "-time: no written time 0.007 (times: 0 0.005 0.01 0.015 0.02)" -postProcess -time 0.007
refused "$c" "-time '0.01:x': 'x' is not a time" -postProcess -time 0.01:x
refused "$c" "-time and -latestTime exclude each other" -postProcess -time 0.01 -latestTime
refused "$c" "-func goes with -postProcess" -func energy
refused "$c" "-dry-run does not go with -postProcess" -postProcess -dry-run
d=$work/decomposed
copy restartBodies2D "$d"
cp "$c/system/controlDict" "$d/system/"
mkdir -p "$d/processor0" && cp -r "$c/0.01" "$d/processor0/"
refused "$d" "run reconstructPar first" -postProcess

# ---- a time-varying g: energy's work term from uniform/accelerationWork.
v=$work/vibrated
copy restartBodies2D "$v"
rm "$v/constant/rigidBodies"
cat >"$v/constant/g" <<'EOF'
type: sinusoidal
value: [0, -9.81]
amplitude: 0.002
frequency: 50
direction: [0, 1]
EOF
cat >"$v/system/controlDict" <<'EOF'
application: mpmFoam
endTime: 0.01
deltaT: 2.0e-4
writeControl: timeStep
writeInterval: 10
functions:
  energy: {type: energy, writeInterval: 10}
EOF
run "$v" 1
cp "$v/postProcessing/energy/0/energy.dat" "$work/vibrated.dat"
rm -rf "$v/postProcessing"
post "$v"
[ -e "$v/0.01/uniform/accelerationWork" ] && cmp -s "$work/vibrated.dat" \
    "$v/postProcessing/energy/0/energy.dat" &&
    ok "time-varying g: energy identical to the live run" || bad "time-varying g: energy"

[ "$fail" = 0 ] && echo "postProcess: all checks passed"
exit "$fail"
