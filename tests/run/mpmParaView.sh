#!/usr/bin/env bash
# mpmParaView (docs/utilities.md), the paraFoam-like launcher, on a copy of tests/cases/
# restartBodies2D that mpmFoam has run (a 2D case with rigid bodies):
#  - -help prints the usage; an unknown option, a missing folder, a folder that is not a case
#    and a case with no results are refused (exit 1) with the utilities' messages;
#  - -dry-run writes <case>/mpmParaView.py (or the -script file) and prints it: it names both
#    series, particles.pvd and rigidBodies.pvd, with the case's absolute path, and says 2D;
#    without a top-level particles.pvd it opens every processor*/particles.pvd and
#    processor0/rigidBodies.pvd, and says so; a case path with a space and a quote survives;
#  - the script runs, with a stand-in for ParaView's paraview.simple module under
#    /usr/bin/python3: it opens both series by their absolute paths, colours the points by
#    velocity magnitude, and with MPMPARAVIEW_SCREENSHOT saves a picture;
#  - the launch runs $MPMFOAM_PARAVIEW --script=<script> (a stand-in program here), without
#    MPMPARAVIEW_SCREENSHOT; without ParaView it still writes the script, names the packages
#    and the script, and exits 1;
#  - when pvpython is on PATH (ParaView installed), the script runs in it and saves a PNG
#    (under xvfb-run -a when there is no display; skipped when neither is there).
set -euo pipefail
root=${MPMFOAM_DIR:-$(cd "$(dirname "$0")/../.." && pwd)}
bin=$root/bin
py=${MPMFOAM_PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=1

fail() {
    echo "FAIL: $*"
    exit 1
}
[ -x "$bin/mpmParaView" ] || fail "$bin/mpmParaView is missing or not executable"
[ -x "$bin/mpmFoam" ] || fail "$bin/mpmFoam is not built"

# expectError TEXT CMD...: CMD exits 1 and its standard error contains TEXT.
expectError() {
    local text=$1 rc=0
    shift
    "$@" >"$work/out" 2>"$work/err" || rc=$?
    [ "$rc" -eq 1 ] || { cat "$work/out" "$work/err"; fail "exit $rc (expected 1): $*"; }
    grep -qF -- "$text" "$work/err" || { cat "$work/err"; fail "'$text' not in the message of: $*"; }
}

# ---- options and refusals
"$bin/mpmParaView" -help >"$work/out" 2>&1 || fail "-help exits non-zero"
grep -q "^Usage: mpmParaView" "$work/out" || fail "-help prints no usage"
expectError "Invalid option: -noSuchOption" "$bin/mpmParaView" -noSuchOption
grep -q "^Usage: mpmParaView" "$work/err" || fail "an unknown option does not print the usage"
expectError "-case needs a directory" "$bin/mpmParaView" -case
expectError "the case directory does not exist" "$bin/mpmParaView" -case "$work/noSuchCase" -dry-run
mkdir -p "$work/notACase"
expectError "not a case directory: it has no system/controlDict" \
    "$bin/mpmParaView" -case "$work/notACase" -dry-run
c=$work/case
cp -r "$root/tests/cases/restartBodies2D" "$c"
expectError "no results to open" "$bin/mpmParaView" -case "$c" -dry-run
[ ! -e "$c/mpmParaView.py" ] || fail "a case with no results got a script"
echo "mpmParaView: usage and refusals"

# ---- a run case with bodies: -dry-run
"$bin/mpmFoam" -case "$c" >"$c/log.mpmFoam" 2>&1 || { tail -20 "$c/log.mpmFoam"; fail "mpmFoam run"; }
for f in particles.pvd rigidBodies.pvd; do
    [ -f "$c/$f" ] || fail "the run wrote no $f"
done
(cd "$c" && "$bin/mpmParaView" -dry-run) >"$work/out" 2>"$work/err" || { cat "$work/err"; fail "-dry-run in the case"; }
s=$c/mpmParaView.py
[ -f "$s" ] || fail "-dry-run wrote no $s"
grep -qF "wrote $s (opens particles.pvd rigidBodies.pvd)" "$work/out" || { cat "$work/out"; fail "-dry-run does not say what it wrote"; }
grep -qF "particleSeries = ['particles.pvd']" "$work/out" || fail "-dry-run does not print the script"
grep -qF "caseDir = '$c'" "$s" || fail "the script does not hold the case's absolute path"
grep -qF "particleSeries = ['particles.pvd']" "$s" || fail "the script does not name particles.pvd"
grep -qF "bodySeries = ['rigidBodies.pvd']" "$s" || fail "the script does not name rigidBodies.pvd"
grep -qF "twoD = True" "$s" || fail "a 2D case is not seen as 2D"
grep -qF "('POINTS', 'velocity', 'Magnitude')" "$s" || fail "the points are not coloured by velocity magnitude"
"$py" -c 'import ast, sys; ast.parse(open(sys.argv[1]).read())' "$s" || fail "the script is not valid Python"
"$bin/mpmParaView" -case "$c" -script "$work/views/other.py" -dry-run >/dev/null 2>&1 &&
    fail "-script into a missing folder succeeded"
mkdir -p "$work/views"
"$bin/mpmParaView" -case "$c" -script "$work/views/other.py" -dry-run >/dev/null || fail "-script"
grep -qF "# GUI:       paraview --script=$work/views/other.py" "$work/views/other.py" ||
    fail "-script: the script does not name itself"
# The same script but for its own name in the comments.
cmp -s <(grep -v '^#' "$s") <(grep -v '^#' "$work/views/other.py") || fail "-script writes another script than the default"
echo "mpmParaView: -dry-run writes and prints a script naming both series"

# ---- the script runs: a stand-in for paraview.simple records what it is asked to do
stub=$work/stub/paraview
mkdir -p "$stub"
: >"$stub/__init__.py"
cat >"$stub/simple.py" <<'PY'
"""Stand-in for ParaView's paraview.simple: logs every call and attribute set to $STUB_LOG.
Only the names below exist, so a script using any other function fails with a NameError."""
import os

_log = open(os.environ["STUB_LOG"], "a")
__all__ = ["GetActiveViewOrCreate", "PVDReader", "Show", "ColorBy", "GetColorTransferFunction",
           "GetScalarBar", "GetTimeKeeper", "GetAnimationScene", "FindSource",
           "GetDisplayProperties", "GetActiveCamera", "SaveScreenshot", "Render"]


class _Proxy:
    def __init__(self, name):
        self.__dict__["_name"] = name

    def __setattr__(self, key, value):
        _log.write("%s.%s = %r\n" % (self._name, key, value))

    def __getattr__(self, key):
        if key == "TimestepValues":
            return [0.0, 0.03, 0.06]
        if key == "ViewTime":
            return 0.06

        def call(*args, **kwargs):
            _log.write("%s.%s%r %r\n" % (self._name, key, args, kwargs))
            return _Proxy(self._name + "." + key)
        return call


def __getattr__(name):
    if name not in __all__:
        raise AttributeError(name)

    def call(*args, **kwargs):
        _log.write("%s%r %r\n" % (name, args, kwargs))
        if name == "SaveScreenshot":
            open(args[0], "wb").write(b"PNG")
        return _Proxy(name)
    return call
PY
runStub() { # runStub LOG SCRIPT [SCREENSHOT]
    : >"$1"
    env STUB_LOG="$1" PYTHONPATH="$work/stub" PYTHONDONTWRITEBYTECODE=1 \
        ${3:+MPMPARAVIEW_SCREENSHOT="$3"} "$py" "$2" >"$work/stubOut" 2>&1 ||
        { cat "$work/stubOut"; fail "the script fails under the paraview.simple stand-in: $2"; }
}
runStub "$work/gui.log" "$s"
grep -qF "PVDReader() {'registrationName': 'particles.pvd', 'FileName': '$c/particles.pvd'}" "$work/gui.log" ||
    { cat "$work/gui.log"; fail "the script does not open $c/particles.pvd"; }
grep -qF "PVDReader() {'registrationName': 'rigidBodies.pvd', 'FileName': '$c/rigidBodies.pvd'}" "$work/gui.log" ||
    fail "the script does not open $c/rigidBodies.pvd"
grep -qF "('POINTS', 'velocity', 'Magnitude')" "$work/gui.log" ||
    fail "the script does not colour by velocity magnitude"
grep -qF "InteractionMode = '2D'" "$work/gui.log" || fail "the script does not set 2D interaction"
! grep -q "SaveScreenshot" "$work/gui.log" || fail "a screenshot without MPMPARAVIEW_SCREENSHOT"
runStub "$work/batch.log" "$s" "$work/shot.png"
grep -q "^SaveScreenshot('$work/shot.png'" "$work/batch.log" || fail "no screenshot with MPMPARAVIEW_SCREENSHOT"
grep -qF "AnimationTime = 0.06" "$work/batch.log" || fail "the screenshot is not of the last time"
grep -qF "mpmParaView: saved the view at t = 0.06 to $work/shot.png" "$work/stubOut" || fail "the screenshot is not reported"
echo "mpmParaView: the script opens both series and colours by velocity magnitude (paraview.simple stand-in)"

# ---- decomposed output only: the processors' series
d=$work/decomposed
mkdir -p "$d"
cp -r "$c/system" "$c/constant" "$d/"
for p in processor0 processor1 processor10; do
    mkdir -p "$d/$p"
    cp "$c/particles.pvd" "$c/rigidBodies.pvd" "$d/$p/"
done
"$bin/mpmParaView" -case "$d" -dry-run >"$work/out" 2>&1 || { cat "$work/out"; fail "-dry-run on processor series"; }
grep -q "has no particles.pvd; opening the decomposed series processor0/particles.pvd processor1/particles.pvd processor10/particles.pvd" "$work/out" ||
    { cat "$work/out"; fail "the processor series are not named in order"; }
grep -qF "particleSeries = ['processor0/particles.pvd', 'processor1/particles.pvd', 'processor10/particles.pvd']" "$d/mpmParaView.py" ||
    fail "the script does not open every processor's series"
grep -qF "bodySeries = ['processor0/rigidBodies.pvd']" "$d/mpmParaView.py" || fail "the bodies of processor0 are not opened"
runStub "$work/proc.log" "$d/mpmParaView.py" "$work/proc.png"
[ "$(grep -c "^PVDReader" "$work/proc.log")" = 4 ] || fail "the script does not open 3 processor series and the bodies"
echo "mpmParaView: without particles.pvd it opens processor*/particles.pvd"

# ---- a case path with a space and a quote
q="$work/my case's"
cp -r "$c" "$q"
"$bin/mpmParaView" -case "$q" -dry-run >/dev/null || fail "-dry-run on a path with a space and a quote"
runStub "$work/quote.log" "$q/mpmParaView.py"
grep -qF "'FileName': \"$q/particles.pvd\"" "$work/quote.log" || { cat "$work/quote.log"; fail "a quote in the case path is mangled"; }
echo "mpmParaView: a case path with a space and a quote"

# ---- launching: a stand-in ParaView; no ParaView
fake=$work/fakeParaView
cat >"$fake" <<SH
#!/bin/sh
printf '%s\n' "\$@" >"$work/launched"
echo "screenshot=\${MPMPARAVIEW_SCREENSHOT:-unset}" >>"$work/launched"
SH
chmod +x "$fake"
MPMFOAM_PARAVIEW=$fake MPMPARAVIEW_SCREENSHOT=$work/x.png "$bin/mpmParaView" -case "$c" >"$work/out" 2>&1 ||
    { cat "$work/out"; fail "the launch with a stand-in ParaView"; }
[ "$(cat "$work/launched")" = "--script=$s
screenshot=unset" ] || { cat "$work/launched"; fail "ParaView not started as paraview --script=$s (without MPMPARAVIEW_SCREENSHOT)"; }
rm -f "$s"
expectError "ParaView not found" env MPMFOAM_PARAVIEW=noSuchParaView "$bin/mpmParaView" -case "$c"
[ -f "$s" ] || fail "without ParaView the script is not written"
grep -qF "apt-get install paraview" "$work/err" || fail "without ParaView the message does not name the package paraview"
grep -qF "python3-paraview" "$work/err" || fail "without ParaView the message does not name python3-paraview"
grep -qF "The script is $s." "$work/err" || fail "without ParaView the message does not say where the script is"
echo "mpmParaView: launches \$MPMFOAM_PARAVIEW --script=...; without ParaView: the packages, the script, exit 1"

# ---- the real thing, when ParaView's Python is installed
if command -v pvpython >/dev/null 2>&1; then
    runner=()
    if [ -z "${DISPLAY:-}" ]; then
        if command -v xvfb-run >/dev/null 2>&1; then
            runner=(xvfb-run -a)
        else
            echo "mpmParaView: pvpython found, but no display and no xvfb-run: not run in ParaView"
            exit 0
        fi
    fi
    MPMPARAVIEW_SCREENSHOT=$work/pv.png timeout 300 "${runner[@]}" pvpython "$s" >"$work/pv.log" 2>&1 ||
        { tail -30 "$work/pv.log"; fail "pvpython $s"; }
    [ -s "$work/pv.png" ] || { tail -30 "$work/pv.log"; fail "pvpython $s saved no picture"; }
    grep -q "mpmParaView: saved the view at t = 0.06" "$work/pv.log" || fail "pvpython: not the last time"
    echo "mpmParaView: the script runs in pvpython ($(command -v pvpython)) and saves a picture"
else
    echo "mpmParaView: no pvpython on PATH: the script was not run in ParaView"
fi
echo "mpmParaView: OK"
