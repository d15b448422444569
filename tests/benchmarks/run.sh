#!/usr/bin/env bash
# Throughput benchmark (not a test): runs each case under tests/benchmarks/ with 1 and 2
# threads and prints particle-updates per second, peak memory and the phase breakdown.
#
#   tests/benchmarks/run.sh [-n RUNS] [-t "THREADS ..."] [-o DIR] [-i] [case ...]
#
#   case     a folder of tests/benchmarks/ (block3D, block3DPlastic, block3DViscoelastic, block2D,
#            sparseSlope) or a path to a case folder (default: block3D); or a generated case,
#            polygonSettling:N (N pentagons settled into a heap, then measured) or
#            polygonSettling:N:matrix (N pentagons in sand), written once by
#            tests/benchmarks/polygonSettling/run.py --prepare (its --threads is 1)
#   -n RUNS  whole runs per case and thread count (default 1); the figures are the median,
#            min and max over the runs, the phase table is the median run's
#   -t LIST  thread counts, space- or comma-separated (default "1 2")
#   -o DIR   keep every run's log in DIR (<case>.t<threads>.r<k>.log, and the median run's as
#            <case>.t<threads>.median.log, which tests/benchmarks/roofline.py reads)
#   -i       idle guard, for a machine shared with others: each run starts once the machine
#            has been idle (<= 0.1 CPU-seconds in 2 s), and a run during which other processes used
#            more than 1 % of one core (busy CPU time of /proc/stat less the run's own) is
#            discarded and run again (at most 20 times per run, 10 minutes of waiting per
#            run; the count of discarded runs is printed)
#
# Each run is a fresh copy of the case, `mpmFoam -noFunctionObjects`, OMP_NUM_THREADS set;
# other OMP_* variables pass through. Particle-updates per second is the solver's own figure
# (particles × steps ÷ wall seconds of the step phases, output excluded); peak memory its
# "Peak memory" line (VmHWM). The last lines are machine-readable, one per case and thread count:
#   RESULT case=<c> threads=<t> runs=<n> median=<p-upd/s> min=<..> max=<..> peakMiB=<largest>
# Figures go in docs/benchmarks.md; run on an otherwise idle machine (the load average before
# and after is printed: a load well above 0 means the figures are not an idle machine's).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
solver=${MPMFOAM_SOLVER:-$root/bin/mpmFoam}
runs=1
threads="1 2"
keep=""
guard=0
usage() { sed -n '2,29p' "$0" | sed 's/^# \{0,1\}//'; exit "${1:-0}"; }
while getopts "n:t:o:ih" opt; do
    case $opt in
    n) runs=$OPTARG ;;
    t) threads=${OPTARG//,/ } ;;
    o) keep=$OPTARG ;;
    i) guard=1 ;;
    h) usage 0 ;;
    *) usage 2 >&2 ;;
    esac
done
shift $((OPTIND - 1))
if ! [[ $runs =~ ^[1-9][0-9]*$ ]]; then
    echo "run.sh: -n expects a whole number of runs >= 1, got '$runs'" >&2
    exit 2
fi
for t in $threads; do
    if ! [[ $t =~ ^[1-9][0-9]*$ ]]; then
        echo "run.sh: -t expects thread counts >= 1, got '$t'" >&2
        exit 2
    fi
done
[ -x "$solver" ] || { echo "run.sh: no solver at $solver (build with ./Allwmake)" >&2; exit 2; }
cases=("$@")
[ ${#cases[@]} -eq 0 ] && cases=(block3D)
generated() { [[ $1 =~ ^polygonSettling:[1-9][0-9]*(:matrix)?$ ]]; }
for c in "${cases[@]}"; do
    generated "$c" || [ -d "$root/tests/benchmarks/$c" ] || [ -d "$c" ] ||
        { echo "run.sh: no case '$c' (neither tests/benchmarks/$c nor a folder)" >&2; exit 2; }
done
# Busy CPU time of the machine so far [1/100 s]: user nice system irq softirq steal.
busyTicks() { awk '/^cpu / { print $2 + $3 + $4 + $7 + $8 + $9 }' /proc/stat; }
waitIdle() { # up to 10 minutes
    local b0 b1 k
    for ((k = 0; k < 300; ++k)); do
        b0=$(busyTicks)
        sleep 2
        b1=$(busyTicks)
        ((b1 - b0 <= 10)) && return 0 # <= 0.1 s of CPU time in 2 s
    done
    echo "run.sh: the machine was not idle for 10 minutes (-i)" >&2
    exit 1
}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[ -n "$keep" ] && mkdir -p "$keep"
echo "# $(date -u '+%F %T') UTC, $(nproc) cores, load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
summary=()
for c in "${cases[@]}"; do
    src=$root/tests/benchmarks/$c
    [ -d "$src" ] || src=$c
    name=$(basename "$src")
    if generated "$c"; then # written (and settled) once, then copied for each run
        IFS=: read -r _ count variant <<<"$c"
        name=polygonSettling-N$count${variant:+-$variant}
        src=$work/prepared-$name
        echo "# preparing $c (tests/benchmarks/polygonSettling/run.py --prepare)"
        python3 "$root/tests/benchmarks/polygonSettling/run.py" --prepare "$src" --count "$count" \
            --solver "$solver" ${variant:+--matrix}
    fi
    for t in $threads; do
        : >"$work/rates"
        discarded=0
        for ((r = 1; r <= runs; ++r)); do
            rm -rf "$work/case" && cp -r "$src" "$work/case"
            log=$work/$name.t$t.r$r.log
            ((guard)) && waitIdle
            b0=$(busyTicks)
            TIMEFORMAT='%U %S %R'
            { time OMP_NUM_THREADS=$t "$solver" -case "$work/case" -noFunctionObjects \
                >"$log" 2>&1 || { cat "$log"; exit 1; }; } 2>"$work/time"
            b1=$(busyTicks)
            if ((guard)); then
                # Others' CPU seconds: the machine's busy time less the run's user + system.
                other=$(awk -v b="$((b1 - b0))" 'END { printf "%.2f", b / 100 - $1 - $2 }' "$work/time")
                wall=$(awk 'END { print $3 }' "$work/time")
                if awk -v o="$other" -v w="$wall" 'BEGIN { exit !(o > 0.01 * w) }'; then
                    echo "   (run $r discarded: others used $other CPU-s in $wall s)"
                    ((++discarded <= 20 * runs)) || { echo "run.sh: machine never idle" >&2; exit 1; }
                    r=$((r - 1))
                    continue
                fi
            fi
            rate=$(sed -n 's/^Particle-updates per second: \([^ ]*\).*/\1/p' "$log")
            peak=$(sed -n 's/^Peak memory: \([^ ]*\) MiB.*/\1/p' "$log")
            [ -n "$rate" ] || { cat "$log"; echo "run.sh: no particle-updates line" >&2; exit 1; }
            echo "$rate ${peak:-nan} $r" >>"$work/rates"
            ((guard)) && echo "   (run $r: $rate particle-updates/s; others used $other CPU-s)"
            [ -n "$keep" ] && cp "$log" "$keep/"
        done
        # Median run: the middle one by rate (the lower middle for an even count).
        read -r med lo hi peak medRun < <(sort -g -k1,1 "$work/rates" | awk -v n="$runs" '
            NR == 1 { lo = $1 } { hi = $1; if ($2 + 0 > pk || NR == 1) pk = $2 }
            NR == int((n + 1) / 2) { med = $1; run = $3 }
            END { print med, lo, hi, pk, run }')
        echo "== $name, OMP_NUM_THREADS=$t, $runs run(s): median run $medRun" \
            "$( ((guard)) && echo "($discarded run(s) discarded: machine busy)")"
        sed -n '/^Phase timing/,/^Peak memory/p' "$work/$name.t$t.r$medRun.log"
        [ -n "$keep" ] && cp "$work/$name.t$t.r$medRun.log" "$keep/$name.t$t.median.log"
        summary+=("$(awk -v c="$name" -v t="$t" -v n="$runs" -v m="$med" -v l="$lo" -v h="$hi" \
            -v p="$peak" 'BEGIN { printf "%-16s %7d %5d %9.3f %9.3f %9.3f %10s", c, t, n,
                m / 1e6, l / 1e6, h / 1e6, p }')")
        summary+=("RESULT case=$name threads=$t runs=$runs median=$med min=$lo max=$hi peakMiB=$peak")
    done
done
echo
echo "# load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-16s %7s %5s %9s %9s %9s %10s\n' case threads runs "median M" "min M" "max M" "peak MiB"
for line in "${summary[@]}"; do
    [[ $line == RESULT* ]] || echo "$line"
done
for line in "${summary[@]}"; do
    [[ $line == RESULT* ]] && echo "$line"
done
exit 0
