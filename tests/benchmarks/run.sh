#!/usr/bin/env bash
# Throughput benchmark (not a test): runs each case under tests/benchmarks/ with 1 and 2
# threads and prints particle-updates per second and the phase breakdown.
#   tests/benchmarks/run.sh [case ...]      (default: block3D)
# Figures go in docs/benchmarks.md; run on an otherwise idle machine.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
solver=$root/bin/mpmFoam
cases=("$@")
[ ${#cases[@]} -eq 0 ] && cases=(block3D)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for c in "${cases[@]}"; do
    for threads in 1 2; do
        rm -rf "$work/$c" && cp -r "$root/tests/benchmarks/$c" "$work/$c"
        echo "== $c, OMP_NUM_THREADS=$threads"
        OMP_NUM_THREADS=$threads "$solver" -case "$work/$c" -noFunctionObjects >"$work/log" 2>&1 ||
            { cat "$work/log"; exit 1; }
        sed -n '/^Phase timing/,/^Particle-updates/p' "$work/log"
    done
done
