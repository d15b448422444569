#!/usr/bin/env bash
# Run control (issue: foundation §6–7): -dry-run writes nothing; SIGUSR1 writes and continues;
# SIGUSR2 and SIGTERM write and stop with exit 0 and "End"; a `stop` file does the same;
# runTimeModifiable re-reads controlDict (stopAt writeNow); a finished case run again says
# endTime is reached and writes nothing; purgeWrite keeps the last N;
# an unstable fixed deltaT (allowed on purpose) stops with exit 1 naming step, phase and
# particle, after writing the last good state, and never writes NaN.
set -euo pipefail
. "$(dirname "$0")/../tools/scriptTest.sh"
ok() { echo "ok: $*"; }
bad() { echo "FAIL: $*"; fail=1; }

# A case that runs for a long time (the signals arrive mid-run).
mk() {
    rm -rf "$1" && cp -r "$root/tests/cases/restart2D" "$1"
    sed -i 's/^endTime:.*/endTime: 1000/; s/^writeInterval:.*/writeInterval: 500/' "$1/system/controlDict"
}
ntimes() { find "$1" -maxdepth 1 -regex '.*/[0-9.e+-]+' -type d | wc -l; }

# -dry-run: one step, nothing written.
mk "$work/dry"
"$solver" -case "$work/dry" -dry-run >"$work/dry.log" 2>&1 && grep -q "^End" "$work/dry.log" &&
    [ "$(ntimes "$work/dry")" -eq 0 ] && [ ! -e "$work/dry/particles.pvd" ] && [ ! -e "$work/dry/postProcessing" ] &&
    ok "-dry-run runs one step and writes nothing" || bad "-dry-run"

# Signals.
for sig in USR1 USR2 TERM; do
    c=$work/sig$sig
    mk "$c"
    "$solver" -case "$c" >"$c.log" 2>&1 &
    pid=$!
    for _ in $(seq 100); do grep -q "Starting time loop" "$c.log" 2>/dev/null && break; sleep 0.1; done
    sleep 0.5
    kill -s "$sig" "$pid"
    if [ "$sig" = USR1 ]; then
        for _ in $(seq 100); do [ "$(ntimes "$c")" -ge 2 ] && break; sleep 0.1; done
        kill -0 "$pid" 2>/dev/null && [ "$(ntimes "$c")" -ge 2 ] && ok "SIGUSR1 wrote a time directory and the run goes on" ||
            bad "SIGUSR1"
        kill -s TERM "$pid"
    fi
    rc=0
    wait "$pid" || rc=$?
    if [ "$rc" -eq 0 ] && grep -q "^End" "$c.log" && [ "$(ntimes "$c")" -ge 2 ]; then
        ok "SIG$sig: wrote, printed End, exit 0"
    else
        bad "SIG$sig (exit $rc)"; tail -5 "$c.log"
    fi
done

# A `stop` file in the case.
c=$work/stopFile
mk "$c"
"$solver" -case "$c" >"$c.log" 2>&1 &
pid=$!
sleep 1
touch "$c/stop"
rc=0
wait "$pid" || rc=$?
[ "$rc" -eq 0 ] && [ ! -e "$c/stop" ] && [ "$(ntimes "$c")" -ge 2 ] && ok "stop file: wrote and stopped" || bad "stop file (exit $rc)"

# runTimeModifiable: stopAt writeNow edited in while running.
c=$work/modify
mk "$c"
"$solver" -case "$c" >"$c.log" 2>&1 &
pid=$!
sleep 1
echo "stopAt: writeNow" >>"$c/system/controlDict"
rc=0
wait "$pid" || rc=$?
[ "$rc" -eq 0 ] && grep -q "Re-read system/controlDict" "$c.log" && [ "$(ntimes "$c")" -ge 2 ] &&
    ok "runTimeModifiable: stopAt writeNow honoured" || bad "runTimeModifiable (exit $rc)"

# A finished case run again: it says endTime is reached, exits 0 and writes nothing.
c=$work/finished
rm -rf "$c" && cp -r "$root/tests/cases/restart2D" "$c"
sed -i 's/^endTime:.*/endTime: 0.01/; s/^writeInterval:.*/writeInterval: 0.01/' "$c/system/controlDict"
"$solver" -case "$c" >"$c.log1" 2>&1 || bad "finished case: the first run failed"
state() { (cd "$c" && find . -printf '%p %s %T@\n' | LC_ALL=C sort); }
before=$(state)
rc=0
"$solver" -case "$c" >"$c.log" 2>&1 || rc=$?
expected="endTime 0.01 reached at time 0.01: nothing to do (raise endTime in system/controlDict to continue)"
if [ "$rc" -eq 0 ] && grep -qF "$expected" "$c.log" && grep -q "^End" "$c.log" &&
    ! grep -q "Starting time loop" "$c.log" && [ "$before" = "$(state)" ]; then
    ok "finished case run again: '$expected', exit 0, nothing written"
else
    bad "finished case run again (exit $rc)"; tail -5 "$c.log"; diff <(echo "$before") <(state) | head -5
fi
sed -i 's/^endTime:.*/endTime: 0.02/' "$c/system/controlDict"
rc=0
"$solver" -case "$c" >"$c.log2" 2>&1 || rc=$?
[ "$rc" -eq 0 ] && grep -q "Restart from time 0.01" "$c.log2" && [ -d "$c/0.02" ] &&
    ok "endTime raised: the run continues to 0.02" || bad "endTime raised (exit $rc)"

# purgeWrite keeps the newest N time directories and the .pvd follows.
c=$work/purge
rm -rf "$c" && cp -r "$root/tests/cases/restart2D" "$c"
sed -i 's/^endTime:.*/endTime: 0.05/; s/^writeInterval:.*/writeInterval: 0.01/' "$c/system/controlDict"
echo "purgeWrite: 2" >>"$c/system/controlDict"
"$solver" -case "$c" >"$c.log" 2>&1
[ "$(ntimes "$c")" -eq 2 ] && [ "$(grep -c '<DataSet' "$c/particles.pvd")" -eq 2 ] && [ -d "$c/0.05" ] &&
    ok "purgeWrite 2 keeps 2 time directories and 2 .pvd entries" || bad "purgeWrite"

# Blow-up: a fixed deltaT 4x the stable limit.
c=$work/blowUp
rm -rf "$c" && cp -r "$root/tests/cases/restart2D" "$c"
cat >"$c/system/controlDict" <<'CD'
application: mpmFoam
endTime: 1.0
deltaT: 0.004
allowUnstableDeltaT: yes
writeControl: timeStep
writeInterval: 1000
CD
rc=0
"$solver" -case "$c" >"$c.log" 2>"$c.err" || rc=$?
if [ "$rc" -eq 1 ] && grep -q "FATAL ERROR" "$c.err" && grep -q "step [0-9]" "$c.err" && grep -q "phase" "$c.err" &&
    grep -q "particle [0-9]" "$c.err" && grep -q "last good state" "$c.err"; then
    ok "unstable deltaT stops with exit 1: $(grep -m1 'step' "$c.err")"
else
    bad "blow-up detection (exit $rc)"; cat "$c.err"
fi
"$py" - "$c" <<'PY' || bad "blow-up output contains non-finite values"
import sys, os, glob, numpy as np, vtk
from vtk.util.numpy_support import vtk_to_numpy
for f in glob.glob(os.path.join(sys.argv[1], "*", "particles.vtu")):
    r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(f); r.Update(); o = r.GetOutput()
    assert np.isfinite(vtk_to_numpy(o.GetPoints().GetData())).all(), f
    pd = o.GetPointData()
    for i in range(pd.GetNumberOfArrays()):
        assert np.isfinite(vtk_to_numpy(pd.GetArray(i))).all(), (f, pd.GetArrayName(i))
print("ok: every written state is finite")
PY
exit $fail
