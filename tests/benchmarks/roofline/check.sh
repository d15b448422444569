#!/usr/bin/env bash
# Check of the benchmark tools against known answers (ctest: benchmarkTools).
#   tests/benchmarks/roofline/check.sh [path/to/rooflineProbe]
#  1. rooflineProbe: a short run passes its own result checks (FMA chains against their closed
#     form, read/copy/triad against the known array values) and prints one ROOFLINE line per
#     thread count with positive figures; bad options are refused with exit 2 and a message.
#  2. roofline.py: the phase model's totals are the hand counts of docs/benchmarks.md (the bytes
#     since "Stores that do not read": streamed arrays once, stencils padded), and a
#     synthetic log (10⁷ particle-steps, P2G 1.106 s) gives P2G exactly 10.00 GFLOP/s.
#  3. run.sh: three runs of a small case give a RESULT line with min <= median <= max and a
#     peak memory; bad options and a missing case are refused with exit 2.
#  4. phaseStats.py / yieldShare.py on a 2D block at rest of 4 × 4 cells, 4 points per cell,
#     whose counts are known: 7 × 7 nodes with mass for 64 points (0.765625 per point), one
#     particle block whose 3 × 3 block neighbourhood has 144 nodes (2.25 per point), bᵉ = 1
#     (no Jacobi sweep) and zero stress (every point at the apex).
set -uo pipefail
root=$(cd "$(dirname "$0")/../../.." && pwd)
probe=${1:-$root/build/tests/rooflineProbe}
py=/usr/bin/python3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fails=0
ok() { echo "PASS: $*"; }
bad() { echo "FAIL: $*"; fails=$((fails + 1)); }

# 1. The probe.
if "$probe" -threads 1,2 -reps 1 -mib 8 -seconds 0.01 >"$work/probe" 2>&1 &&
    [ "$(grep -c '^ROOFLINE threads=[12] ' "$work/probe")" -eq 2 ] &&
    awk '/^ROOFLINE/ { for (i = 3; i <= NF; ++i) { split($i, kv, "="); if (!(kv[2] > 0)) exit 1 } }' \
        "$work/probe"; then
    ok "rooflineProbe: checks pass, two ROOFLINE lines with positive figures"
else
    cat "$work/probe"; bad "rooflineProbe short run"
fi
# refused NAME ARGS COMMAND...: COMMAND ARGS must exit 2 with a "NAME: " message.
refused() {
    local name=$1 args=$2
    shift 2
    # shellcheck disable=SC2086
    "$@" $args >"$work/err" 2>&1
    local rc=$?
    if [ $rc -eq 2 ] && grep -q "^$name: " "$work/err"; then
        ok "$name $args refused: $(grep "^$name: " "$work/err" | head -1)"
    else
        bad "$name $args: exit $rc"
    fi
}
for args in "-reps 0" "-threads 1,a" "-mib 0.5" "-bogus 1" "-seconds"; do
    refused rooflineProbe "$args" "$probe"
done

# 2. roofline.py: hand counts and a synthetic log.
$py "$root/tests/benchmarks/roofline.py" --model-table >"$work/model" 2>&1
for row in "block3D | P2G | 1106 |" "block3D | G2P | 994 |" "block2D | P2G | 279 |" \
    "block2D | G2P | 260 |" "block3D | sort | 6 | 137 |" "block3D | P2G | 1106 | 513 |"; do
    if grep -qF "| $row" "$work/model"; then ok "model: $row"; else bad "model row '$row'"; fi
done
cat >"$work/log" <<'EOF'
Phase timing (100 steps, 100000 particles, 2 threads):
    sort               0.100 s    2.0 %
    P2G                1.106 s   20.0 %
    grid               0.010 s    0.2 %
    G2P                0.994 s   20.0 %
    constitutive       1.000 s   20.0 %
    functions          0.000 s    0.0 %
    IO                 0.000 s    0.0 %
    total              3.210 s  100.0 %
Particle-updates per second: 3e+06 (3 M)
EOF
if $py "$root/tests/benchmarks/roofline.py" --probe "$work/probe" --run "block3D=$work/log" \
    --out "$work/chart.png" >"$work/table" 2>&1 &&
    grep -qF "| block3D | P2G | 110.6 | 2.16 | 10.00 |" "$work/table" &&
    grep -qF "| block3D | G2P | 99.4 | 1.69 | 10.00 |" "$work/table" && [ -s "$work/chart.png" ]; then
    ok "roofline.py: P2G and G2P at 10.00 GFLOP/s from the synthetic log, chart written"
else
    cat "$work/table"; bad "roofline.py on the synthetic log"
fi
$py "$root/tests/benchmarks/roofline.py" --probe "$work/probe" --run "nosuch=$work/log" \
    >"$work/err" 2>&1 && bad "roofline.py accepted an unknown model" ||
    ok "roofline.py refuses an unknown model: $(tail -1 "$work/err")"

# 3. run.sh on a small case (12 x 12 x 11 cells, 8 points per cell, 10 steps).
small=$work/small3D
cp -r "$root/tests/benchmarks/block3D" "$small"
sed -i 's/cellSize: 0.02/cellSize: 0.04/' "$small/constant/grid"
sed -i 's/endTime: 0.01/endTime: 0.0005/' "$small/system/controlDict"
if bash "$root/tests/benchmarks/run.sh" -n 3 -t 1 -o "$work/logs" "$small" >"$work/run" 2>&1 &&
    awk '/^RESULT/ { for (i = 2; i <= NF; ++i) { split($i, kv, "="); v[kv[1]] = kv[2] }
                     n++; if (!(v["runs"] == 3 && v["min"] <= v["median"] && v["median"] <= v["max"] &&
                     v["peakMiB"] > 0)) exit 1 } END { exit n == 1 ? 0 : 1 }' "$work/run" &&
    [ -s "$work/logs/small3D.t1.median.log" ] && [ -s "$work/logs/small3D.t1.r3.log" ] &&
    grep -q "^Peak memory: .* MiB (VmHWM)" "$work/logs/small3D.t1.median.log"; then
    ok "run.sh -n 3: $(grep '^RESULT' "$work/run")"
else
    cat "$work/run"; bad "run.sh -n 3 on a small case"
fi
for args in "-n 0" "-t 1,x" "$work/nosuch"; do
    refused run.sh "$args" bash "$root/tests/benchmarks/run.sh"
done

# 4. phaseStats.py and yieldShare.py on a 2D block at rest.
rest=$work/rest2D
mkdir -p "$rest/constant" "$rest/system"
cat >"$rest/constant/grid" <<'EOF'
dimension: 2
bounds: {min: [0, 0], max: [0.4, 0.4]}
cellSize: 0.04
EOF
cat >"$rest/constant/particles" <<'EOF'
block:
  material: soil
  region: {type: box, min: [0.04, 0.04], max: [0.2, 0.2]}
  seeding: {method: regular, perDirection: 2}
EOF
echo 'soil: {type: henckyElastic, density: 2000, E: 1.0e6, nu: 0.3}' >"$rest/constant/materials"
printf 'application: mpmFoam\nendTime: 0.0005\ndeltaT: 5.0e-5\nwriteControl: timeStep\nwriteInterval: 5\n' \
    >"$rest/system/controlDict"
printf 'kernel: quadraticBSpline\ntransfer: apic\nstressUpdate: USL\n' >"$rest/system/mpmSchemes"
if OMP_NUM_THREADS=1 "$root/bin/mpmFoam" -case "$rest" >"$work/rest.log" 2>&1 &&
    $py "$root/tests/benchmarks/phaseStats.py" "$rest" >"$work/stats" 2>&1 &&
    grep -qF "STATS case=rest2D activeNodes=2.2500 massNodes=0.7656 sweeps=0.000 plasticShare=0.000" \
        "$work/stats"; then
    ok "phaseStats.py: $(tail -1 "$work/stats")"
else
    cat "$work/rest.log" "$work/stats"; bad "phaseStats.py on the 2D block at rest"
fi
if $py "$root/tests/benchmarks/yieldShare.py" "$rest/0.0005/particles.vtu" 30 >"$work/share" 2>&1 &&
    grep -qF "64 points, phi = 30.0 deg (mu = 0.6928): on the cone 0.0 %, at the apex 100.0 %" \
        "$work/share"; then
    ok "yieldShare.py: $(head -1 "$work/share")"
else
    cat "$work/share"; bad "yieldShare.py on the 2D block at rest"
fi

echo "$fails failure(s)"
[ $fails -eq 0 ]
