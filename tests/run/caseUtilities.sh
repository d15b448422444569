#!/usr/bin/env bash
# mpmCloneCase, mpmListTimes and mpmDictionary (docs/utilities.md) on a copy of
# tests/cases/restart2D that mpmFoam has run (times 0 … 0.01), with the clutter of a used case
# added (logs, stop, processor0/, a write in progress, scripts, a level set, a runs/ folder):
#  - every utility prints its usage with -help and rejects an unknown option;
#  - mpmListTimes lists the times in numeric order (1e-05 first, 0.01 after 0.008), without 0
#    unless -withZero, never a .<time>.writing folder; -latestTime; -processor; -rm removes
#    the times and their particles.pvd entries, never 0/, constant/ or system/;
#  - mpmCloneCase copies system/, constant/ (level sets too), 0/ (or with -latestTime the
#    latest time) and the top-level scripts, not the results; refuses an existing target and a
#    folder that is not a case, leaving nothing behind; the clone passes mpmFoam -dry-run;
#  - mpmDictionary prints entries, values and keys; -set and -remove change only the lines of
#    the entry (every other line, comments included, stays byte for byte); edits whose value
#    or result does not parse, or that would turn a map into a scalar, are refused with the
#    file untouched; a missing entry is an error naming it.
set -euo pipefail
root=${MPMFOAM_DIR:-$(cd "$(dirname "$0")/../.." && pwd)}
bin=$root/bin
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=1

fail() {
    echo "FAIL: $*"
    exit 1
}
for u in mpmCloneCase mpmListTimes mpmDictionary mpmFoam; do
    [ -x "$bin/$u" ] || fail "$bin/$u is not built"
done

# expectError CMD...: CMD must exit 1; its standard error is left in $work/err.
expectError() {
    local rc=0
    "$@" >"$work/out" 2>"$work/err" || rc=$?
    [ "$rc" -eq 1 ] || { cat "$work/out" "$work/err"; fail "exit $rc (expected 1): $*"; }
}
# expectText EXPECTED CMD...: CMD succeeds and prints exactly EXPECTED.
expectText() {
    local expected=$1 got
    shift
    got=$("$@" 2>"$work/err") || { cat "$work/err"; fail "failed: $*"; }
    [ "$got" = "$expected" ] || fail "$*: printed
$got
expected
$expected"
}

# ---- -help and unknown options
for u in mpmCloneCase mpmListTimes mpmDictionary; do
    "$bin/$u" -help >"$work/out" 2>&1 || fail "$u -help exits non-zero"
    grep -q "^Usage: $u" "$work/out" || fail "$u -help prints no usage"
    expectError "$bin/$u" -noSuchOption
    grep -q "Invalid option: -noSuchOption" "$work/err" || fail "$u: unknown option not named"
done
echo "caseUtilities: -help prints the usage, unknown options are refused"

# ---- a run case with the clutter of a used one
c=$work/case
cp -r "$root/tests/cases/restart2D" "$c"
"$bin/mpmDictionary" "$c/system/controlDict" -entry endTime -set 0.01
"$bin/mpmDictionary" "$c/system/controlDict" -entry writeInterval -set 0.002
"$bin/mpmFoam" -case "$c" >"$c/log.mpmFoam" 2>&1 || { cat "$c/log.mpmFoam"; fail "mpmFoam run"; }
cp -r "$c/0.002" "$c/1e-05" # a time mpmFoam names with an exponent (written by a smaller step)
mkdir -p "$c/.0.012.writing/uniform" "$c/processor0/0.002" "$c/processor1/0.002" \
    "$c/runs/old/system" "$c/constant/levelSets"
touch "$c/.0.012.writing/particles.vtu" "$c/stop" "$c/log.decomposePar" "$c/rigidBodies.pvd"
printf 'levelSet\n' >"$c/constant/levelSets/body.vti"
printf '#!/bin/sh\necho run\n' >"$c/Allrun"
printf '#!/bin/sh\necho clean\n' >"$c/Allclean"
chmod +x "$c/Allrun" "$c/Allclean"
printf 'print("particles")\n' >"$c/makeParticles.py"
printf '# case\n' >"$c/README.md"
[ -f "$c/particles.pvd" ] && [ -d "$c/postProcessing" ] || fail "the run wrote no particles.pvd or postProcessing/"

# ---- mpmListTimes
times=$'1e-05\n0.002\n0.004\n0.006\n0.008\n0.01'
[ "$(cd "$c" && ls -d [0-9]* | grep -vx 0)" != "$times" ] || fail "the names sort alike by text: no test of the numeric order"
expectText "$times" "$bin/mpmListTimes" -case "$c"
expectText "$times" sh -c "cd '$c' && '$bin/mpmListTimes'"
expectText $'0\n'"$times" "$bin/mpmListTimes" -case "$c" -withZero
expectText 0.01 "$bin/mpmListTimes" -case "$c" -latestTime
expectText 0.002 "$bin/mpmListTimes" -case "$c" -processor
expectError "$bin/mpmListTimes" -case "$work/nowhere"
expectError "$bin/mpmListTimes" -case "$c/constant"
grep -q "system/controlDict" "$work/err" || fail "mpmListTimes: a folder that is no case is not named as such"
expectError "$bin/mpmListTimes" -case "$c" -rm -withZero
[ -d "$c/0" ] || fail "mpmListTimes -rm -withZero removed 0/"
echo "caseUtilities: mpmListTimes lists $(echo "$times" | wc -l) times in numeric order, -withZero, -latestTime, -processor"

# ---- mpmCloneCase
"$bin/mpmCloneCase" "$c" "$work/clone" >"$work/out" || { cat "$work/out"; fail "mpmCloneCase"; }
for f in system/controlDict system/mpmSchemes constant/grid constant/materials constant/particles \
    constant/g constant/levelSets/body.vti 0/particles.vtu 0/uniform/time Allrun Allclean \
    makeParticles.py README.md; do
    cmp -s "$c/$f" "$work/clone/$f" || fail "mpmCloneCase: $f not copied (or differs)"
done
[ -x "$work/clone/Allrun" ] || fail "mpmCloneCase: Allrun lost its execute permission"
for f in 0.002 0.01 1e-05 .0.012.writing processor0 processor1 postProcessing runs particles.pvd \
    rigidBodies.pvd log.mpmFoam log.decomposePar stop; do
    [ ! -e "$work/clone/$f" ] || fail "mpmCloneCase copied the result $f"
done
grep -q "runs/" "$work/out" || fail "mpmCloneCase does not say that runs/ was left out"
"$bin/mpmFoam" -case "$work/clone" -dry-run >"$work/log" 2>&1 || { cat "$work/log"; fail "the clone does not pass mpmFoam -dry-run"; }

"$bin/mpmCloneCase" "$c" "$work/latest" -latestTime >/dev/null
[ -d "$work/latest/0.01" ] && [ ! -e "$work/latest/0" ] && [ ! -e "$work/latest/0.008" ] ||
    fail "mpmCloneCase -latestTime: expected 0.01/ alone, got: $(ls "$work/latest" | tr '\n' ' ')"
diff -r "$c/0.01" "$work/latest/0.01" >/dev/null || fail "mpmCloneCase -latestTime: 0.01/ differs"

touch "$work/clone/marker"
expectError "$bin/mpmCloneCase" "$c" "$work/clone"
grep -q "already exists" "$work/err" || fail "mpmCloneCase: existing target not reported"
[ -f "$work/clone/marker" ] && [ ! -e "$work/clone/clone" ] || fail "mpmCloneCase wrote into an existing folder"
expectError "$bin/mpmCloneCase" "$c/constant" "$work/fromNoCase"
grep -q "system/controlDict" "$work/err" || fail "mpmCloneCase: a source that is no case is not named as such"
[ ! -e "$work/fromNoCase" ] || fail "mpmCloneCase created the target of a refused clone"
expectError "$bin/mpmCloneCase" "$c"
ls -A "$work" | grep -q cloning && fail "mpmCloneCase left a staging folder behind"
echo "caseUtilities: mpmCloneCase copies the set-up, not the results; -latestTime; refusals"

# ---- mpmListTimes -rm (after the clones, which needed the times)
expectText "Removed 0.01" "$bin/mpmListTimes" -case "$c" -rm -latestTime
[ ! -e "$c/0.01" ] && [ -d "$c/0.008" ] || fail "mpmListTimes -rm -latestTime"
grep -q '"0.01/' "$c/particles.pvd" && fail "mpmListTimes -rm left 0.01 in particles.pvd"
grep -q '"0.008/' "$c/particles.pvd" || fail "mpmListTimes -rm dropped 0.008 from particles.pvd"
"$bin/mpmListTimes" -case "$c" -processor -rm >/dev/null
[ ! -e "$c/processor0/0.002" ] && [ ! -e "$c/processor1/0.002" ] && [ -d "$c/0.002" ] ||
    fail "mpmListTimes -processor -rm"
"$bin/mpmListTimes" -case "$c" -rm >/dev/null
expectText 0 "$bin/mpmListTimes" -case "$c" -withZero
[ -f "$c/0/particles.vtu" ] && [ -f "$c/system/controlDict" ] && [ -f "$c/constant/grid" ] &&
    [ -d "$c/.0.012.writing" ] || fail "mpmListTimes -rm removed more than the times"
[ "$(grep -c '<DataSet' "$c/particles.pvd")" -eq 1 ] || fail "particles.pvd keeps removed times"
echo "caseUtilities: mpmListTimes -rm removes the times (not 0/) and their particles.pvd entries"

# ---- mpmDictionary: reading
d=$work/dict
mkdir -p "$d"
cp "$root/cases/glassDrop40/system/controlDict" "$d/controlDict"
cp "$root/cases/glassDrop40/constant/grid" "$d/grid"
cp "$d/controlDict" "$d/controlDict.orig"
cp "$d/grid" "$d/grid.orig"
chmod 640 "$d/controlDict"
expectText 0.1 "$bin/mpmDictionary" "$d/controlDict" -entry endTime -value
expectText "endTime: 0.1" "$bin/mpmDictionary" "$d/controlDict" -entry endTime
expectText 0.08 "$bin/mpmDictionary" "$d/controlDict" -entry functions.depth.surface -value
expectText $'loadCell\nsphere\ndepth\ngap\nenergy' "$bin/mpmDictionary" "$d/controlDict" -entry functions -keywords
expectText "[0.224, 0.10, 0.16]" "$bin/mpmDictionary" "$d/grid" -entry bounds.max -value
expectError "$bin/mpmDictionary" "$d/controlDict" -entry functions.dpth -value
grep -q "functions.dpth" "$work/err" && grep -q "did you mean 'depth'" "$work/err" ||
    fail "mpmDictionary: missing entry not named: $(cat "$work/err")"
expectError "$bin/mpmDictionary" "$d/controlDict" -entry noSuchKey -remove
grep -q "noSuchKey" "$work/err" || fail "mpmDictionary -remove: missing entry not named"
expectError "$bin/mpmDictionary" "$d/controlDict" -entry endTime -keywords
cmp -s "$d/controlDict" "$d/controlDict.orig" || fail "mpmDictionary changed the file on a refused request"

# ---- mpmDictionary: edits change the entry's lines only
# check FILE EXPECTED-FILE WHAT: the edited file equals the expected text byte for byte.
check() {
    diff "$2" "$1" >"$work/diff" || { cat "$work/diff"; fail "mpmDictionary $3: other lines changed"; }
}
"$bin/mpmDictionary" "$d/controlDict" -entry endTime -set 0.2
sed 's/^endTime: 0.1 /endTime: 0.2 /' "$d/controlDict.orig" >"$d/expected"
check "$d/controlDict" "$d/expected" "-set endTime (comment kept)"
"$bin/mpmDictionary" "$d/controlDict" -entry functions.gap.writeInterval -set 20
sed -i 's/^    writeInterval: 10$/    writeInterval: 20/' "$d/expected"
check "$d/controlDict" "$d/expected" "-set functions.gap.writeInterval"
"$bin/mpmDictionary" "$d/controlDict" -entry functions.energy -remove
sed -i '/^  energy:$/,/^    writeInterval: 50$/d' "$d/expected"
check "$d/controlDict" "$d/expected" "-remove functions.energy"
"$bin/mpmDictionary" "$d/controlDict" -entry functions.mass.type -set centreOfMass
printf '  mass:\n    type: centreOfMass\n' >>"$d/expected"
check "$d/controlDict" "$d/expected" "-set a new functions.mass.type"
expectText centreOfMass "$bin/mpmDictionary" "$d/controlDict" -entry functions.mass.type -value
[ "$(stat -c %a "$d/controlDict")" = 640 ] || fail "mpmDictionary lost the file's permissions"
"$bin/mpmDictionary" "$d/grid" -entry bounds.max -set '[1, 1, 0.5]'
sed 's/^bounds: .*/bounds: {min: [0, 0, 0], max: [1, 1, 0.5]}/' "$d/grid.orig" >"$d/expectedGrid"
check "$d/grid" "$d/expectedGrid" "-set in a flow map"
"$bin/mpmDictionary" "$d/grid" -entry boundary.zMax -set slip
sed -i 's/^  zMax: open$/  zMax: slip/' "$d/expectedGrid"
check "$d/grid" "$d/expectedGrid" "-set boundary.zMax"
echo "caseUtilities: mpmDictionary -set/-remove keep every other line and comment"

# ---- mpmDictionary: refused edits leave the file alone
cp "$d/controlDict" "$d/before"
expectError "$bin/mpmDictionary" "$d/controlDict" -entry endTime -set '[1, 2'
grep -q "not YAML" "$work/err" || fail "mpmDictionary: unparsable value not reported"
expectError "$bin/mpmDictionary" "$d/controlDict" -entry functions -set 1
grep -q "map" "$work/err" || fail "mpmDictionary: map set to a scalar not reported"
expectError "$bin/mpmDictionary" "$d/controlDict" -entry endTime.x -set 1
cmp -s "$d/controlDict" "$d/before" || fail "mpmDictionary changed the file on a refused edit"
printf 'a: &size 1   # anchored\nb: *size\n' >"$d/anchors"
cp "$d/anchors" "$d/anchors.orig"
expectError "$bin/mpmDictionary" "$d/anchors" -entry a -set 2 # the alias would dangle
grep -q "unreadable" "$work/err" || fail "mpmDictionary: an edit that breaks the file not reported"
cmp -s "$d/anchors" "$d/anchors.orig" || fail "mpmDictionary wrote an edit that does not parse"
ls -A "$d" | grep -q mpmDictionary && fail "mpmDictionary left a temporary file"
echo "caseUtilities: mpmDictionary refuses edits that do not parse or change a map's type"
echo "caseUtilities: PASS"
