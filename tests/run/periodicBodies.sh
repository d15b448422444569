#!/usr/bin/env bash
# Rigid bodies across periodic seams (src/rigid/BodySet wrap, src/contact/Coupling images,
# docs/caseFormat.md §4 "Periodic faces and rigid bodies"): what tests/cases/periodicBody2D's
# README says must hold.
#
#  A: the case as shipped (disk from x = 0.3, crosses the seam at t ~ 0.05 s);
#  B: the disk half a period further (x = 0.1, crosses at t ~ 0.16 s); the layer fills the box,
#     so it is its own half-period shift.
#  1. B = A shifted by L/2: points matched by position at t = 0, at every write x_B = wrap(x_A +
#     L/2), v, sigma equal; the disk's position (wrapped), velocity and angular velocity equal.
#  2. no point is ever inside the disk, through the seam included (minimum image), at every
#     write; contactGap: the gap before the safety projection stays > 0 at every step (the
#     barrier alone kept the points out), and points touched the disk through the seam.
#  3. x momentum of layer + disk conserved (slip floor, no other horizontal force).
#  4. the disk wrapped: every written disk x in [0, 0.4); A: 1 vs 2 threads bit-identical;
#     restarts from A's and B's own t = 0.1 (A after its disk wrapped, B before) bit-identical
#     to the uninterrupted runs (particles.vtu and uniform/rigidBodies).
set -euo pipefail
. "$(dirname "$0")/../tools/scriptTest.sh"
same() { # label dirA dirB times...: particles.vtu and uniform/rigidBodies bit-identical
    local label=$1 a=$2 b=$3 n=0 bad=""
    shift 3
    for t in "$@"; do
        if cmp -s "$a/$t/particles.vtu" "$b/$t/particles.vtu" &&
            cmp -s "$a/$t/uniform/rigidBodies" "$b/$t/uniform/rigidBodies"; then
            n=$((n + 1))
        else bad="$bad $t"; fi
    done
    if [ -z "$bad" ]; then
        echo "$label: particles.vtu and uniform/rigidBodies bit-identical at $n writes"
        return 0
    fi
    echo "FAIL: $label: differs at t =$bad"
    return 1
}

cat >"$work/check.py" <<'PY'
import os, re, sys
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

L, R, MDISK = 0.4, 0.04, 10.0
fail = False
def check(ok, label, detail):
    global fail
    print(("%s: %s" if ok else "FAIL: %s: %s") % (label, detail))
    fail |= not ok

def times(case):
    return sorted((d for d in os.listdir(case)
                   if os.path.isfile(os.path.join(case, d, "particles.vtu"))), key=float)

def read(case, t):
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(os.path.join(case, t, "particles.vtu"))
    r.Update()
    o = r.GetOutput()
    pd = o.GetPointData()
    d = {"x": vtk_to_numpy(o.GetPoints().GetData()).astype(float)[:, :2]}
    for i in range(pd.GetNumberOfArrays()):
        d[pd.GetArrayName(i)] = vtk_to_numpy(pd.GetArray(i))
    order = np.argsort(d["id"], kind="stable")
    return {k: v[order] for k, v in d.items()}

def body(case, t):
    text = open(os.path.join(case, t, "uniform", "rigidBodies")).read()
    def vec(key):
        return np.array([float(v) for v in re.search(key + r": \[([^\]]*)\]", text).group(1).split(",")])
    return {"x": vec("position"), "v": vec("velocity"), "w": vec("omegaBody")[2]}

def dat(path):
    lines = open(path).read().splitlines()
    cols = [l for l in lines if l.startswith("#")][-1][1:].split()
    a = np.loadtxt([l for l in lines if l and not l.startswith("#")], ndmin=2)
    return {c: a[:, i] for i, c in enumerate(cols)}

def ended(case):
    lines = [l.strip() for l in open(os.path.join(case, "log.mpmFoam")).read().splitlines() if l.strip()]
    return bool(lines) and lines[-1] == "End"

def wrapd(d):  # minimum image of a separation along x
    return d - L * np.round(d / L)

A, B = sys.argv[1], sys.argv[2]
ts = times(A)
check(ended(A) and ended(B) and ts == times(B) and len(ts) >= 20, "periodicBody2D",
      "A and B end with End, %d writes each" % len(ts))

# 1. B = A shifted by L/2. Pair the points by position at t = 0.
a0, b0 = read(A, "0"), read(B, "0")
key = lambda x, y: np.round(x / 1e-7).astype(np.int64) * 10**8 + np.round(y / 1e-7).astype(np.int64)
ka = key(np.mod(a0["x"][:, 0] + L / 2, L), a0["x"][:, 1])
kb = key(b0["x"][:, 0], b0["x"][:, 1])
ia, ib = np.argsort(ka), np.argsort(kb)
paired = len(ka) == len(kb) and np.array_equal(ka[ia], kb[ib])
ex = ey = ev = es = eb = ew = 0.0
for t in ts:
    a, b = read(A, t), read(B, t)
    if not paired or not (np.array_equal(a["id"], a0["id"]) and np.array_equal(b["id"], b0["id"])):
        paired = False
        break
    ex = max(ex, np.abs(wrapd(b["x"][ib, 0] - a["x"][ia, 0] - L / 2)).max())
    ey = max(ey, np.abs(b["x"][ib, 1] - a["x"][ia, 1]).max())
    ev = max(ev, np.abs(b["velocity"][ib] - a["velocity"][ia]).max())
    smax = np.abs(a["stress"]).max()
    es = max(es, np.abs(b["stress"][ib] - a["stress"][ia]).max() / smax if smax > 0 else
             (0.0 if np.array_equal(a["stress"], b["stress"]) else np.inf))
    ba, bb = body(A, t), body(B, t)
    eb = max(eb, abs(wrapd(bb["x"][0] - ba["x"][0] - L / 2)), abs(bb["x"][1] - ba["x"][1]),
             np.abs(bb["v"] - ba["v"]).max())
    ew = max(ew, abs(bb["w"] - ba["w"]))
check(paired and ex < 1e-9 and ey < 1e-9, "periodicBody2D",
      "1. x_B = wrap(x_A + L/2) within %.3g m, y_B = y_A within %.3g m (1e-9), %d points paired"
      % (ex, ey, len(ka)))
check(paired and ev < 1e-8 and es < 1e-6, "periodicBody2D",
      "1. |v_B - v_A| %.3g m/s (1e-8), |sigma_B - sigma_A| / max|sigma_A| %.3g (1e-6)" % (ev, es))
check(paired and eb < 1e-9 and ew < 1e-6, "periodicBody2D",
      "1. disk: position (wrapped) and velocity within %.3g (1e-9), angular velocity within %.3g rad/s (1e-6)"
      % (eb, ew))

# 2. no penetration, through the seam included.
for case, name in ((A, "A"), (B, "B")):
    worst, seam, xs = 1e300, 0, []
    for t in ts:
        p, d = read(case, t), body(case, t)
        xs.append(d["x"][0])
        dx = p["x"][:, 0] - d["x"][0]
        gap = np.hypot(wrapd(dx), p["x"][:, 1] - d["x"][1]) - R
        worst = min(worst, gap.min())
        seam += int(((gap < 0.01) & (np.abs(dx) > L / 2)).sum())  # near the disk through the seam
    g = dat(os.path.join(case, "postProcessing/gap/0/gap.dat"))
    bd = dat(os.path.join(case, "postProcessing/body/0/body.dat"))
    late = g["time"] > 0
    check(worst > 0 and seam > 0, "periodicBody2D " + name,
          "2. smallest distance of a point to the disk surface (minimum image) at the %d writes: %.4g m "
          "(> 0); %d point-writes within 1 cm of the disk through the seam" % (len(ts), worst, seam))
    straddle = late & (np.minimum(bd["disk_x"], L - bd["disk_x"]) < R) & (g["contacts"] > 0)
    touching = late & (g["contacts"] > 0)
    check(g["minimumGapBeforeProjection"][late].min() > 0 and touching.sum() > 0.9 * late.sum()
          and straddle.sum() >= 50, "periodicBody2D " + name,
          "2. contactGap: gap before the projection >= %.4g m at every step (> 0); points in contact at "
          "%d of %d steps (> 90 %%; up to %d points), %d of them with the disk across the seam (>= 50)"
          % (g["minimumGapBeforeProjection"][late].min(), touching.sum(), late.sum(),
             g["contacts"].max(), straddle.sum()))
    wrapped = min(xs) >= 0 and max(xs) < L and any(x < 0.1 for x in xs) and any(x > 0.3 for x in xs)
    check(wrapped, "periodicBody2D " + name,
          "4. written disk x in [%.4f, %.4f] (in [0, 0.4), on both sides of the box: it wrapped)"
          % (min(xs), max(xs)))
    # 3. x momentum: the layer (centreOfMass: M v_c) + the disk (rigidBodyState), every step.
    c = dat(os.path.join(case, "postProcessing/centre/0/centre.dat"))
    b = dat(os.path.join(case, "postProcessing/body/0/body.dat"))
    P = c["mass"] * c["vx"] + MDISK * b["disk_vx"]
    dp = np.abs(P - P[0]).max() / abs(P[0])
    pts = [read(case, t) for t in ts]
    Pw = [(q["mass"] * q["velocity"][:, 0]).sum() + MDISK * body(case, t)["v"][0] for q, t in zip(pts, ts)]
    dw = np.abs(np.array(Pw) - Pw[0]).max() / abs(Pw[0])
    moved = np.abs(c["mass"] * c["vx"]).max()
    check(dp < 1e-8 and dw < 1e-12 and moved > 0.1 * abs(P[0]), "periodicBody2D " + name,
          "3. x momentum layer + disk: P0 = %.6g N s/m, max |P - P0|/P0 %.3g every step (monitors, "
          "10 digits; 1e-8), %.3g at the writes (full precision; 1e-12); the layer took up to %.3g N s/m"
          % (P[0], dp, dw, moved))
sys.exit(1 if fail else 0)
PY

A=$work/A B=$work/B
copy periodicBody2D "$A"
copy periodicBody2D "$B"
sed -i 's/position: \[0.39, 0.105\]/position: [0.19, 0.105]/' "$B/constant/rigidBodies"
grep -q 'position: \[0.19, 0.105\]' "$B/constant/rigidBodies" || { echo "FAIL: editing B failed"; exit 1; }
run "$A" 2
run "$B" 2
"$py" "$work/check.py" "$A" "$B" || fail=1

# 4. threads
copy periodicBody2D "$A.1"
run "$A.1" 1
# shellcheck disable=SC2046
same "periodicBody2D A: 4. 1 vs 2 threads" "$A.1" "$A" $(writes "$A") || fail=1
for m in body gap centre; do
    cmp -s "$A/postProcessing/$m/0/$m.dat" "$A.1/postProcessing/$m/0/$m.dat" ||
        { echo "FAIL: periodicBody2D A: 4. $m.dat differs between 1 and 2 threads"; fail=1; }
done

# 4. restart from the uninterrupted runs' own t = 0.1 (A's disk has wrapped, B's has not).
for c in A B; do
    d=$work/$c
    S=$work/$c.resume
    mkdir -p "$S" && cp -r "$d/constant" "$d/system" "$d/0.1" "$S/"
    run "$S" 2
    grep -q "Restart from time 0.1" "$S/log.mpmFoam" || { echo "FAIL: $c did not restart from 0.1"; fail=1; }
    later=$(writes "$d" | awk '$1 > 0.1 + 1e-9')
    # shellcheck disable=SC2086
    same "periodicBody2D $c: 4. restart from 0.1 vs uninterrupted" "$d" "$S" $later || fail=1
done

[ $fail -eq 0 ] && echo "periodicBodies: all checks passed"
exit $fail
