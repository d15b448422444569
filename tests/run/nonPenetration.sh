#!/usr/bin/env bash
# Non-penetration (granular-impact issue §3): a steel sphere fired into sand at ten times the
# 60 cm impact speed (34.3 m/s), sampled every step by contactGap.
#
# barrier: after every step the coupling projects points closer than ξ_min back out
# (Coupling::enforceGap), so the smallest ξ after it (column 2) is > 0 by construction: that
# tests the safety net. The barrier itself is tested by the smallest ξ *before* the projection
# (column 5, minimumGapBeforeProjection). At 34.3 m/s a point closes 0.14 r_p per step on the
# sphere while the steep part of the barrier is 0.2 r_p thick: the barrier force alone lets points
# 0.2 mm in before the projection (a known limit, docs/granularImpact.md), so the barrier alone is
# asserted at half that speed (17.2 m/s, run `barrierHalfSpeed`), and at 34.3 m/s only the gap
# after the projection.
#
# linearSpring (the original MP-DEM, f = k_N (r_p - ξ) [000 §3.2]) has no projection (column 5
# equals column 2). At its default k_N = k_N,crit (8.4e4 N/m here) the points stay out at this
# speed, so the run uses k_N = 2.1e4 N/m (k_N,crit/4): the spring must let points in (ξ < 0,
# [000 §3.2]: its force at ξ = 0 is only k_N r_p), and the recorded depth must agree with the
# spring law. The contact forces of step n act at the positions the previous step ended at, where
# the gap monitor recorded ξ_min(n-1); frictionless, |F_body(n)| = |Σ f_i| ≤ Σ k_N (r_p - ξ_i)
# ≤ N(n) k_N (r_p - ξ_min(n-1)): the deepest point is at least as deep as the mean overlap the
# spring needs to carry the body force (rigidBodyState F, contactGap contacts N).
set -euo pipefail
root=${MPMFOAM_DIR:-$(cd "$(dirname "$0")/../.." && pwd)}
solver=$root/bin/mpmFoam
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
stiffness=2.1e4 # N/m
fail=0
for run in barrier barrierHalfSpeed linearSpring; do
    law=${run%HalfSpeed}
    c=$work/$run
    cp -r "$root/tests/cases/fastImpact3D" "$c"
    [ "$run" = barrierHalfSpeed ] && sed -i "s/velocity: \[0, 0, -34.3103\]/velocity: [0, 0, -17.1552]/" "$c/constant/rigidBodies"
    coupling="type: $law"
    [ "$law" = linearSpring ] && coupling="$coupling, stiffness: $stiffness"
    sed -i "s/coupling: {type: barrier}/coupling: {$coupling}/" "$c/constant/rigidBodies"
    if ! "$solver" -case "$c" >"$c/log" 2>&1; then
        echo "FAIL: $law: mpmFoam failed"; tail -5 "$c/log"; fail=1; continue
    fi
    gapFile=$c/postProcessing/gap/0/gap.dat
    gap=$(awk '!/^#/ && (m == "" || $2 < m) {m = $2} END {print m}' "$gapFile")
    before=$(awk '!/^#/ && (m == "" || $5 < m) {m = $5; t = $1} END {print m, t}' "$gapFile")
    rows=$(grep -vc '^#' "$gapFile")
    steps=$(awk '/Phase timing/ {gsub(/\(/, ""); print $3}' "$c/log")
    # r_p = V_p^(1/3), V_p = bed volume / number of points (Poisson-disk seeding: all equal).
    n=$(awk '/Starting time loop/ {for (i = 1; i <= NF; ++i) if ($i == "with") print $(i + 1)}' \
        "$c/log")
    rp=$(awk -v n="$n" 'BEGIN {printf "%.6e", (0.224 * 0.104 * 0.08 / n)^(1 / 3)}')
    echo "$run: $rows samples ($steps steps), r_p = $rp m: smallest gap after projection" \
         "$gap m, before projection ${before% *} m (t = ${before#* } s)"
    [ "$rows" -ge "$steps" ] || { echo "FAIL: $law: contactGap did not sample every step"; fail=1; }
    if [ "$law" = barrier ]; then
        awk -v g="$gap" 'BEGIN {exit !(g > 0)}' ||
            { echo "FAIL: barrier: a point ended a step inside the sphere (gap $gap)"; fail=1; }
        [ "$run" = barrier ] ||
            awk -v g="${before% *}" 'BEGIN {exit !(g > 0)}' ||
            { echo "FAIL: $run: the barrier force let a point into the sphere before the" \
                   "projection (gap ${before% *} m at t = ${before#* } s)"; fail=1; }
    else
        awk -v g="${before% *}" -v a="$gap" 'BEGIN {exit !(g < 0 && g == a)}' ||
            { echo "FAIL: linearSpring: expected ξ < 0 and no projection (before ${before% *}," \
                   "after $gap)"; fail=1; }
        awk -v k="$stiffness" -v rp="$rp" '
            FNR == 1 {file++}
            /^#/ {next}
            file == 1 {gapAfter[$1] = prev; prev = $2; contacts[$1] = $4}
            file == 2 && contacts[$1] > 0 && gapAfter[$1] < 1e299 {
                F = sqrt($11 * $11 + $12 * $12 + $13 * $13)
                mean = F / (contacts[$1] * k); deepest = rp - gapAfter[$1]
                if (mean > deepest * (1 + 1e-9)) {bad++; if (bad == 1) at = $1}
                if (mean / deepest > worst) worst = mean / deepest
                checked++
            }
            END {
                printf "linearSpring: %d steps, mean overlap |F|/(N k_N) / deepest overlap <= %.3f\n",
                       checked, worst
                if (checked == 0 || bad) {
                    printf "FAIL: linearSpring: %d steps (first t = %s) where the recorded gap is " \
                           "shallower than the spring force requires\n", bad, at
                    exit 1
                }
            }' "$gapFile" "$c/postProcessing/sphere/0/sphere.dat" || fail=1
    fi
done
[ $fail -eq 0 ] && echo "nonPenetration: no point ends a step inside at 34.3 m/s; the barrier" \
    "alone keeps every point outside at 17.2 m/s"
exit $fail
