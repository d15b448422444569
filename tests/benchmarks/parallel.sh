#!/usr/bin/env bash
# Parallel benchmark (not a test, docs/parallel.md): one rank with 2 threads against 2 ranks with
# 1 thread each (mpirun, bisection decomposition), the same case, runs interleaved.
#
#   tests/benchmarks/parallel.sh [-n RUNS] [case ...]
#
#   case     a folder of tests/benchmarks/ (default: block3D block3DPlastic block2D)
#   -n RUNS  pairs of runs per case (default 3); the figures are medians
#
# Prints per case and layout the particle-updates per second (the solver's figure: particles ×
# steps ÷ wall seconds of the step phases), the time per step and the share of it spent in
# communication (halo, migration, reductions: the "of which comm" line), and the halo bytes per
# step; the last lines are machine-readable:
#   RESULT case=<c> layout=<1x2|2x1> median=<p-upd/s> stepMs=<ms> comm=<%>
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
bin=$root/bin
runs=3
while getopts "n:h" opt; do
    case $opt in
    n) runs=$OPTARG ;;
    *) sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//'; exit 2 ;;
    esac
done
shift $((OPTIND - 1))
cases=${*:-block3D block3DPlastic block2D}
if [ "$(id -u)" = 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
median() { sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
results=()
for c in $cases; do
    src=$root/tests/benchmarks/$c
    for layout in 1x2 2x1; do : > "$work/$c.$layout"; done
    for ((k = 1; k <= runs; ++k)); do
        for layout in 1x2 2x1; do
            d=$work/$c.$layout.run
            rm -rf "$d"
            cp -r "$src" "$d"
            if [ $layout = 1x2 ]; then
                OMP_NUM_THREADS=2 "$bin/mpmFoam" -case "$d" -noFunctionObjects > "$d/log" 2>&1
            else
                printf "numberOfSubdomains: 2\nmethod: bisection\n" > "$d/system/decomposeParDict"
                "$bin/decomposePar" -case "$d" > /dev/null
                mpirun --oversubscribe -np 2 -x OMP_NUM_THREADS=1 "$bin/mpmFoam" -case "$d" \
                    -parallel -noFunctionObjects > "$d/log" 2>&1
            fi
            awk -v layout=$layout '
                /^Phase timing/ { gsub(/[(,]/, " "); steps = $3 }
                /^    total/ { total = $2 }
                /of which comm/ { comm = $4 }
                /Particle-updates per second:/ { pups = $4 }
                /halo/ { for (i = 1; i <= NF; ++i) if ($i == "halo") halo = $(i + 1) }
                END {
                    share = 0; if (total > 0) share = 100 * comm / total
                    if (halo == "") halo = 0
                    printf "%s %.6g %.6g %s\n", pups, 1000 * total / steps, share, halo
                }' \
                "$d/log" >> "$work/$c.$layout"
        done
    done
    for layout in 1x2 2x1; do
        f=$work/$c.$layout
        p=$(cut -d' ' -f1 "$f" | median); s=$(cut -d' ' -f2 "$f" | median)
        m=$(cut -d' ' -f3 "$f" | median); h=$(cut -d' ' -f4 "$f" | median)
        printf "%-16s %s: %.3g particle-updates/s, %.3g ms per step, comm %.1f %%, halo %s KiB/step\n" \
            "$c" "$layout" "$p" "$s" "$m" "$h"
        results+=("RESULT case=$c layout=$layout median=$p stepMs=$s comm=$m")
    done
done
printf '%s\n' "${results[@]}"
