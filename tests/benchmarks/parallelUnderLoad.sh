#!/usr/bin/env bash
# Ranks under load (benchmark, not a test; docs/parallel.md "Ranks under load"): the 2D column
# collapse of tutorials/parallel/columnCollapse at h = 2.5 mm (12 800 points, 1 000 steps), one
# rank of one thread against 2 ranks of one thread (mpirun, bisection), with 0, 1 and 2 busy
# loops on the same cores as the background load. Runs interleaved, medians.
#
#   tests/benchmarks/parallelUnderLoad.sh [-n RUNS] [-m 'MPIRUN OPTIONS']
#
#   -n RUNS   runs of each layout per load (default 3)
#   -m OPTS   extra mpirun options for the 2-rank runs (e.g. '--mca mpi_yield_when_idle 1')
#
# Prints per load the median step time of each layout (the solver's "total" of the phase table:
# the time stepping, start-up excluded) and the ratio 2 ranks / serial; the last lines are
# machine-readable:
#   RESULT load=<busy loops> serial=<s> ranks2=<s> ratio=<ranks2/serial>
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
bin=$root/bin
runs=3
mpiOptions=
while getopts "n:m:h" opt; do
    case $opt in
    n) runs=$OPTARG ;;
    m) mpiOptions=$OPTARG ;;
    *) sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; exit 2 ;;
    esac
done
if [ "$(id -u)" = 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
work=$(mktemp -d)
loads=()
cleanup() {
    for pid in "${loads[@]}"; do kill "$pid" 2> /dev/null || true; done
    rm -rf "$work"
}
trap cleanup EXIT

for layout in serial ranks2; do
    d=$work/$layout
    mkdir -p "$d"
    cp -r "$root/tutorials/parallel/columnCollapse/system" "$root/tutorials/parallel/columnCollapse/constant" "$d/"
    sed -i 's/^cellSize:.*/cellSize: 0.0025/' "$d/constant/grid"
    sed -i 's/^endTime:[^#]*/endTime: 0.05 /' "$d/system/controlDict"
done
printf 'numberOfSubdomains: 2\nmethod: bisection\n' > "$work/ranks2/system/decomposeParDict"
"$bin/decomposePar" -case "$work/ranks2" > "$work/decomposePar.log" 2>&1

# The step time of one run of a layout: the "total" line of the (slowest rank's) phase table.
runOnce() {
    local d=$work/$1
    rm -rf "$d"/0.[0-9]* "$d"/processor*/0.[0-9]* "$d/postProcessing"
    if [ "$1" = serial ]; then
        OMP_NUM_THREADS=1 "$bin/mpmFoam" -case "$d" > "$d/log" 2>&1
    else
        # shellcheck disable=SC2086
        OMP_NUM_THREADS=1 mpirun --oversubscribe -np 2 -x OMP_NUM_THREADS $mpiOptions \
            "$bin/mpmFoam" -case "$d" -parallel > "$d/log" 2>&1
    fi
    awk '$1 == "total" {print $2}' "$d/log"
}
median() { sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }

results=()
for load in 0 1 2; do
    while [ "${#loads[@]}" -lt "$load" ]; do
        sh -c 'while :; do :; done' &
        loads+=($!)
    done
    : > "$work/serial.times"
    : > "$work/ranks2.times"
    for ((k = 1; k <= runs; ++k)); do
        runOnce serial >> "$work/serial.times"
        runOnce ranks2 >> "$work/ranks2.times"
    done
    s=$(median < "$work/serial.times")
    r=$(median < "$work/ranks2.times")
    ratio=$(awk -v a="$r" -v b="$s" 'BEGIN {printf "%.2f", a / b}')
    printf '%d busy loops: serial %s s, 2 ranks %s s, ratio %s\n' "$load" "$s" "$r" "$ratio"
    results+=("RESULT load=$load serial=$s ranks2=$r ratio=$ratio")
done
printf '%s\n' "${results[@]}"
