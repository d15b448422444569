#!/usr/bin/env bash
# Installation (README.md "Install", cmake/Install.cmake). Usage: install.sh <build dir>
#  1. `cmake --install <build dir> --prefix <temporary folder>` succeeds and writes the tree:
#     the programs in bin/, bin/tools/ (RunFunctions, CleanFunctions, the Python helpers; not
#     the developer tools), etc/bashrc, tutorials/, cases/, docs/;
#  2. the installed tutorials hold no run output (time directories, runs/, postProcessing/,
#     processor<N>/, logs, .pvd, pictures), even while CTest runs the tutorials in the source
#     tree next to this test;
#  3. in a clean environment (env -i, PATH=/usr/bin:/bin, no MPMFOAM_DIR) the installed
#     etc/bashrc sets MPMFOAM_DIR to the prefix and puts its bin/ on PATH; `mpmFoam -help`
#     works; tutorials/verification/elasticColumn, copied out of the installed tree, runs with
#     its Allrun and passes its validate, and its Allclean cleans the copy.
# Nothing here reads the source tree: only the build tree's install rules.
set -euo pipefail
build=${1:?usage: install.sh <build dir>}
build=$(cd "$build" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/mpmFoam
fail() {
    echo "FAIL: $*"
    exit 1
}

# ---- 1. install
cmake --install "$build" --prefix "$prefix" >"$work/log.install" 2>&1 ||
    { tail -20 "$work/log.install"; fail "cmake --install $build --prefix $prefix"; }
for p in mpmFoam surfaceToLevelSet decomposePar reconstructPar mpmCloneCase mpmListTimes \
    mpmDictionary; do
    if [ ! -x "$prefix/bin/$p" ] || [ -L "$prefix/bin/$p" ]; then fail "bin/$p not installed"; fi
done
for f in bin/tools/RunFunctions bin/tools/CleanFunctions bin/tools/verification.py \
    etc/bashrc README.md docs/caseFormat.md cases/glassDrop40/Allrun \
    tutorials/verification/elasticColumn/validate; do
    [ -f "$prefix/$f" ] || fail "$f not installed"
done
[ -x "$prefix/tutorials/verification/elasticColumn/Allrun" ] ||
    fail "tutorials/verification/elasticColumn/Allrun not installed executable"
for f in bin/tools/checkFormat bin/tools/installDependencies; do
    [ ! -e "$prefix/$f" ] || fail "$f (a developer tool) installed"
done
echo "install: cmake --install wrote bin/ ($(find "$prefix/bin" -maxdepth 1 -type f | wc -l)" \
    "programs), bin/tools/, etc/bashrc, tutorials/, cases/, docs/"

# ---- 2. no run output in the installed tutorials and cases
output=$(find "$prefix/tutorials" "$prefix/cases" \
    \( -type d \( -name '[0-9]*' -o -name runs -o -name postProcessing -o -name 'processor[0-9]*' \
    -o -name __pycache__ \) -print -prune \) -o \
    \( -type f \( -name 'log.*' -o -name '*.pvd' -o -name '*.vtu' -o -name '*.vti' \) -print \))
pictures=$(find "$prefix/tutorials" -name '*.png')
[ -z "$output$pictures" ] || fail "run output installed:
$(printf '%s\n%s\n' "$output" "$pictures" | head -20)"
echo "install: no run output in the installed tutorials and cases"

# ---- 3. the installed tree on its own, in a clean environment
mkdir "$work/run" "$work/home"
# shellcheck disable=SC2016 # the script expands in the clean shell
env -i PATH=/usr/bin:/bin HOME="$work/home" OMP_WAIT_POLICY=passive \
    bash --noprofile --norc -c '
set -eu
prefix=$1 run=$2
fail() { echo "FAIL: $*"; exit 1; }
set +u
. "$prefix/etc/bashrc"
set -u
[ "$MPMFOAM_DIR" = "$prefix" ] || fail "etc/bashrc sets MPMFOAM_DIR=$MPMFOAM_DIR, not $prefix"
[ "$(command -v mpmFoam)" = "$prefix/bin/mpmFoam" ] ||
    fail "mpmFoam on PATH is $(command -v mpmFoam || echo nothing), not $prefix/bin/mpmFoam"
mpmFoam -help >"$run/help" 2>&1 || { cat "$run/help"; fail "mpmFoam -help exits non-zero"; }
grep -q "^Usage: mpmFoam" "$run/help" || fail "mpmFoam -help prints no usage"
echo "install: etc/bashrc sets MPMFOAM_DIR and PATH; mpmFoam -help works"

cp -r "$MPMFOAM_DIR/tutorials/verification/elasticColumn" "$run/elasticColumn"
cd "$run/elasticColumn"
start=$(date +%s)
./Allrun >log.Allrun 2>&1 || { cat log.Allrun; tail -20 log.mpmFoam 2>/dev/null; fail "elasticColumn: Allrun"; }
grep -q "elasticColumn: PASS" log.validate || { cat log.Allrun; fail "elasticColumn: validate"; }
echo "install: elasticColumn copied from the installed tree runs and passes ($(($(date +%s) - start)) s)"
./Allclean
[ -z "$(ls -d log.* [0-9]* 2>/dev/null)" ] || fail "elasticColumn: Allclean left $(ls)"
' _ "$prefix" "$work/run" || fail "the installed tree in a clean environment (above)"
echo "install: PASS"
