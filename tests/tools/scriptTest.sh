# shellcheck shell=bash
# Shared set-up of the solver-level test scripts (tests/run/*.sh), sourced after `set -euo
# pipefail`: the repository root, the solver, the Python that has VTK, a work folder removed on
# exit, the failure flag, and helpers to run and copy test cases.
root=${MPMFOAM_DIR:-$(cd "$(dirname "$0")/../.." && pwd)}
solver=$root/bin/mpmFoam
py=${MPMFOAM_PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0

# Run mpmFoam on case folder $1 with $2 threads, appending to its log.mpmFoam; stop the script
# with the log's tail on failure.
run() {
    local dir=$1 threads=$2
    OMP_NUM_THREADS=$threads "$solver" -case "$dir" >>"$dir/log.mpmFoam" 2>&1 ||
        { echo "FAIL: mpmFoam failed on $dir"; tail -20 "$dir/log.mpmFoam"; exit 1; }
}
# Copy tests/cases/$1 to a fresh folder $2.
copy() { rm -rf "$2" && cp -r "$root/tests/cases/$1" "$2"; }
# The time directories of case folder $1, in time order.
writes() { find "$1" -mindepth 1 -maxdepth 1 -type d -name '[0-9]*' -printf '%f\n' | sort -g; }
