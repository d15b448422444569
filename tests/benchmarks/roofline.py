#!/usr/bin/python3
"""Roofline chart of the solver's phases (docs/benchmarks.md, "Issue 11 baseline").

    tests/benchmarks/roofline.py --probe PROBE.txt --run block3D=LOG [--run MODEL=LOG ...]
                                 [--threads N] [--out chart.png] [--title TEXT]
    tests/benchmarks/roofline.py --model-table

PROBE.txt is the output of build/tests/rooflineProbe (its ROOFLINE lines); LOG a solver log
with the "Phase timing" table (tests/benchmarks/run.sh -o DIR keeps them); MODEL one of the
phase models below (block3D, block3DPlastic, block3DViscoelastic, block2D). For every phase the script takes the
model's FLOP and bytes per particle-step and the log's phase time, and prints and plots
  achieved GFLOP/s = FLOP/p-step × particles × steps / phase seconds,
  achieved GB/s    = bytes/p-step × particles × steps / phase seconds,
against the probe's peaks for the log's thread count: the vector FMA peak, the scalar FMA
peak, and the triad bandwidth with the write-allocate counted (the bytes that cross the memory
bus). --model-table prints the model (Markdown) and exits.

The phase model (counted from the source, see docs/benchmarks.md for the rules):
  FLOP   every +, −, ×, ÷ and √ of double values as written in the source (an FMA is 2),
         per particle-step; loop-invariant constants are taken as hoisted; comparisons,
         floor/rint, integer and index arithmetic are not counted. The compiler may drop some
         (× 1.0, × 0 is kept) and vectorises some: the figures are source-level work.
  bytes  every particle-array element read or written in the phase (8 B per double or index,
         4 B per int), an array that is only written counted twice (write-allocate), each
         array once per pass that touches it (nothing assumed to stay cached between passes);
         plus the grid's node fields, once per pass over a node (the 27-fold reuse of a node
         by neighbouring particles is assumed to hit in cache), per particle through the
         case's active nodes and nodes with mass per particle (phaseStats.py).
"""
import argparse
import math
import re
import sys


def field_bytes(dim):
    """Bytes of one particle over all fields of Particles::visitTable (no model state)."""
    vec, mat, mat3 = 8 * dim, 8 * dim * dim, 72
    # id, material, v, stress, volume, mass, plasticStrain, volume0, F, be, C, L, x
    return 8 + 4 + vec + mat3 + 8 + 8 + 8 + 8 + mat + mat3 + mat + mat + vec, 13


def viscoelastic_model(d):
    """(FLOP, bytes) per point-step of the constitutive phase of `viscoelasticMuI` (3D):
    Particles::updateDeformation with the rate-form volume [002 Eq. 76], then the 8-lane
    update of src/materials/ViscoelasticMuI.cpp (counted as written; x − 0.0 and the like not)."""
    assert d == 3
    # updateDeformation: 1 + Δt L 12, (1 + Δt L) F 45; V ← V exp(Δt tr L): tr 2, × Δt 1, exp
    # (glibc, a table and a degree-5 polynomial: ~12), × V 1.
    defFlop = 12 + 45 + 2 + 1 + 12 + 1
    defBytes = 72 + 2 * 72 + 4 + 2 * 8  # L, F rw, material, volume rw
    # Gather, per lane (scalar): D 6, Δt w 9, t² 5, Rodrigues' series a and b 11 each (4
    # divisions each: t²/6, /20, /42, /72), ρ = m/V 1.
    gather = 6 + 9 + 5 + 2 * 11 + 1
    # The 8-lane block: t² 5, Q 36, Q σᵉ 45, (Q σᵉ) Qᵀ (6 entries) 30, tr D 2, λΔt tr D 1,
    # σᵉ_tr 15, D_dev 3 + tr/3 1, σ_tr 16 (ϑ tr D 1), p_tr 3, s 3, τ_tr 14 (√), μ_s p 1,
    # α 2 (√), S₂ 1, B 2, H 3, disc 3, τ 4 (√, ÷), γ̇ 2, τ/τ_tr 1, dpScale 2, σ 9, σᵉ 27.
    lanes = (5 + 36 + 45 + 30 + 2 + 1 + 15 + 4 + 16 + 3 + 3 + 14 + 1 + 2 + 1 + 2 + 3 + 3 + 4 + 2 + 1
             + 2 + 9 + 27)
    # Scatter: εp += γ̇ Δt 2, the finite check 13.
    scatter = 2 + 13
    # ids, L, σᵉ rw, m, V, σ w+wa, flowState w+wa, γ̇ w+wa, εp rw
    consBytes = 8 + 72 + 2 * 72 + 8 + 8 + 2 * 72 + 2 * 4 + 2 * 8 + 2 * 8
    return defFlop + gather + lanes + scatter, defBytes + consBytes


def phase_model(dim, plastic, logTerms, expShare, expTerms, activeNodes, massNodes,
                viscoelastic=False):
    """{phase: (FLOP, bytes)} per particle-step for the quadratic B-spline, APIC, USL, Hencky
    (plastic: Drucker–Prager return map) step of src/transfers/Transfer.cpp,
    src/particles/BlockSort.cpp, src/materials/HenckyLaw.hpp / HenckyReturnMap.hpp."""
    d = dim
    vec, mat = 8 * d, 8 * d * d
    stencil = 8 + 2 * 8 * 3 * d + 8 * d  # node0, w and dw (3 per axis), fx
    stencil = 32 * ((stencil + 31) // 32)  # padded to whole 32-byte chunks (streamed)
    # --- sort: BlockSort::update (xh per particle into the radix keys; one counting-sort pass:
    # count, then place key_ and order_), and every ReorderInterval = 20 steps
    # Particles::permute of every field + a second update. (Since 2026-11-27 the kernel
    # weights are evaluated in P2G's pass, below.)
    sortFlop = 2 * d  # xh = (x - origin) / h
    # x; the count evaluates the keys and writes key_ (4 B, w+wa); the placing reads key_ and
    # writes the copies of key_ and order_ (w+wa; the first pass's order is the identity,
    # not read)
    sortBytes = vec + 2 * 4 + 4 + 2 * (4 + 8)
    weightFlop = 2 * d + d * (1 + 1 + 3 + 6 + 1 + 1)
    fb, nfields = field_bytes(d)
    if viscoelastic:  # model state permuted with the rest: elasticStress, plasticStrainRate, flowState
        fb, nfields = fb + 72 + 8 + 4, nfields + 3
    permuteBytes = 3 * fb + 8 * nfields + sortBytes + 2 * 8  # + materialParticles_ lists
    sort = (sortFlop + sortFlop / 20, sortBytes + permuteBytes / 20)
    # --- P2G: grid clear (mass + 4 vectors per active node, write-allocate), then per
    # particle m v, m h C, -V σ/h and the 27 (9) node updates, each node of the stencils
    # read and written once (mass, momentum, force).
    clearBytes = 2 * (8 + 4 * vec)
    if d == 3:
        # scatter3: per z-row 1; per (y, z) row wyz dyz wdz oy 4, p0 = mv + mC (-fx, oy, oz)
        # 18, u 3, v 9; per node wgt 1, mass 2, momentum (a mC.col0 3, + p0 3, × wgt 3, += 3)
        # 12, force (dw u 3, w v 3, + 3, += 3) 12.
        p2gFlop = (3 + 10 + 10) + 3 * 1 + 9 * (4 + 18 + 3 + 9) + 27 * (1 + 2 + 12 + 12)
    else:
        # forStencil: per row oy 1; per node wgt 1, grad 2, offset 1; mass 2, momentum
        # (mC offset 6, + mv 2, × wgt 2, += 2) 12, force (S grad 6, += 2) 8.
        p2gFlop = (2 + 5 + 5) + 3 * 1 + 9 * (4 + 2 + 12 + 8)
    # order, mass, v, C, volume, stress; x, and the stencil it evaluates (weightFlop),
    # streamed (written without write-allocate, src/core/Stream.hpp)
    p2gBytes = 8 + 8 + vec + mat + 8 + 72 + vec + stencil
    p2g = (p2gFlop + weightFlop,
           p2gBytes + clearBytes * activeNodes + 2 * (8 + 2 * vec) * massNodes)
    # --- grid: per active node the mass is read; per node with mass v0 = p/m (d ÷),
    # f = force + m g (2d), v = v0 + (Δt/m) f (1 ÷ + 2d); read p, force, write vOld, v.
    grid = ((d + 2 * d + 1 + 2 * d) * massNodes, 8 * activeNodes + 4 * vec * massNodes)
    # --- G2P (APIC, velocity gradient): reads the stencil and grid v, writes v, C, L, x.
    if d == 3:
        # gather3: per z-row oz 1; per (y, z) row 4 + vPic 6, b0 6, b1 7, b2 7, L 18; per node
        # r0 6, r1 7, r2 6; then B.col0 6, C 10, L 9, x 6, two |v|² 10, finite 2, energy 3.
        g2pFlop = 3 * 1 + 9 * (4 + 6 + 6 + 7 + 7 + 18) + 27 * (6 + 7 + 6) + 6 + 10 + 9 + 6 + 10 + 2 + 3
    else:
        # forStencil: per row 1; per node 4 + vPic 4, B 10, L 8; then C 5, L 4, x 4, |v|² 6,
        # finite 1, energy 3.
        g2pFlop = 3 * 1 + 9 * (4 + 4 + 10 + 8) + 5 + 4 + 4 + 6 + 1 + 3
    # x rw; v w+wa; C, L w+wa, or streamed in 2D (16-byte stores); mass
    cl = 1 if d == 2 else 2
    g2pBytes = stencil + 2 * vec + 2 * vec + cl * mat + cl * mat + 8
    g2p = (g2pFlop, g2pBytes + vec * massNodes)
    # --- constitutive: Particles::updateDeformation (F ← (1 + Δt L) F, V = det F V⁰), then
    # the Hencky update of 8-particle batches (since 2026-11-27 without eigen-decomposition,
    # SymmetricSeries.hpp): f = 1 + Δt L (3×3) 12, b = f b fᵀ 90; ε = ½ ln b = artanh Z:
    # X = b − 1 and 2 + X 6, cofactors 18, det 5, ÷ 1, inverse 6, Z and Z² (2 products), |Z|²
    # 12, logTerms Horner steps (a product + 3), ε = Z S (a product), a product of commuting
    # symmetric tensors being 30 (plane: 10); σ = (λ tr ε 1 + 2G ε)/J 21; elastic: finite check
    # 6; plastic (HenckyReturnMap.hpp): V⁰/V, m/V 2, the lane block (ε_v, ε̂, |ε̂|, q, p, Δγ,
    # ratio, the returned ε and 2ε: 51), in the expShare of batches with a plastic point
    # bᵉ = exp 2ε (|2ε|² 12, expTerms Horner steps of 6 + a product + 3), Δγ 1, finite check 13.
    defFlop = (d * d + d + (2 * d * d * d - d * d) + (14 if d == 3 else 3) + 1)
    defBytes = mat + 2 * mat + 4 + 8 + 2 * 8  # L, F rw, material, volume0, volume w+wa
    product = 30 if d == 3 else 10
    logFlop = 6 + 18 + 5 + 1 + 6 + 2 * product + 12 + logTerms * (product + 3) + product
    if plastic:
        expFlop = expShare * (12 + expTerms * (6 + product + 3))
        consFlop = 12 + 90 + 2 + logFlop + 51 + 21 + expFlop + 1 + 13
        consBytes = 8 + mat + 2 * 72 + 8 + 8 + 8 + 2 * 72 + 2 * 8  # ids L be V⁰ V m σ εp
    else:
        consFlop = 12 + 90 + logFlop + 21 + 6
        consBytes = 8 + mat + 2 * 72 + 8 + 8 + 2 * 72  # ids, L, be rw, V⁰, V, σ w+wa
    cons = (defFlop + consFlop, defBytes + consBytes)
    if viscoelastic:
        cons = viscoelastic_model(d)
    return {"sort": sort, "P2G": p2g, "grid": grid, "G2P": g2p, "constitutive": cons}


# Case inputs of the model (tests/benchmarks/phaseStats.py on a run of each case, 2 threads;
# the series' mean terms per batch and the share of batches with a plastic point counted on
# one run of each case, 2026-11-27).
CASES = {
    "block3D": dict(dim=3, plastic=False, logTerms=1.618, expShare=0.0, expTerms=0.0,
                    activeNodes=0.4091, massNodes=0.1759),
    "block3DPlastic": dict(dim=3, plastic=True, logTerms=1.384, expShare=0.875, expTerms=4.458,
                           activeNodes=0.4091, massNodes=0.1761),
    "block3DViscoelastic": dict(dim=3, plastic=False, logTerms=0.0, expShare=0.0, expTerms=0.0,
                                activeNodes=0.4091, massNodes=0.1759, viscoelastic=True),
    "block2D": dict(dim=2, plastic=False, logTerms=1.279, expShare=0.0, expTerms=0.0,
                    activeNodes=0.2781, massNodes=0.2569),
}
PHASES = ["sort", "P2G", "grid", "G2P", "constitutive"]


def read_probe(path):
    peaks = {}
    for line in open(path):
        if line.startswith("ROOFLINE "):
            kv = dict(item.split("=", 1) for item in line.split()[1:])
            peaks[int(kv["threads"])] = {k: float(v) for k, v in kv.items()}
    if not peaks:
        sys.exit(f"roofline.py: {path}: no ROOFLINE line (the output of rooflineProbe)")
    return peaks


def read_log(path):
    text = open(path).read()
    m = re.search(r"Phase timing \((\d+) steps, (\d+) particles, (\d+) threads\):\n(.*?)\n"
                  r"Particle-updates per second: (\S+)", text, re.S)
    if not m:
        sys.exit(f"roofline.py: {path}: no 'Phase timing' table followed by "
                 "'Particle-updates per second' (a finished mpmFoam log)")
    steps, particles, threads = int(m.group(1)), int(m.group(2)), int(m.group(3))
    times = {}
    for line in m.group(4).splitlines():
        f = re.match(r"\s+(\S.*?)\s+([\d.]+) s\s", line)
        if f:
            times[f.group(1)] = float(f.group(2))
    missing = [p for p in PHASES if p not in times]
    if missing:
        sys.exit(f"roofline.py: {path}: phase(s) {', '.join(missing)} not in the table")
    return dict(steps=steps, particles=particles, threads=threads, times=times,
                pups=float(m.group(5)))


def model_table():
    print("| case | phase | FLOP / p-step | bytes / p-step | FLOP/byte |")
    print("|---|---|---:|---:|---:|")
    for name, c in CASES.items():
        model = phase_model(**c)
        for ph in PHASES:
            f, b = model[ph]
            print(f"| {name} | {ph} | {f:.0f} | {b:.0f} | {f / b:.2f} |")
        f = sum(model[p][0] for p in PHASES)
        b = sum(model[p][1] for p in PHASES)
        print(f"| {name} | **step** | **{f:.0f}** | **{b:.0f}** | {f / b:.2f} |")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--probe", help="rooflineProbe output")
    ap.add_argument("--run", action="append", default=[], metavar="MODEL=LOG")
    ap.add_argument("--threads", type=int, help="peaks of this thread count (default: the logs')")
    ap.add_argument("--out", help="PNG to write")
    ap.add_argument("--title", default="")
    ap.add_argument("--model-table", action="store_true")
    a = ap.parse_args()
    if a.model_table:
        model_table()
        return
    if not a.probe or not a.run:
        ap.error("--probe and at least one --run MODEL=LOG are needed")
    peaks = read_probe(a.probe)
    runs = []
    for spec in a.run:
        if "=" not in spec:
            ap.error(f"--run expects MODEL=LOG, got '{spec}'")
        name, path = spec.split("=", 1)
        if name not in CASES:
            ap.error(f"--run: no model '{name}' (models: {', '.join(CASES)})")
        runs.append((name, read_log(path)))
    threads = a.threads or runs[0][1]["threads"]
    if threads not in peaks:
        sys.exit(f"roofline.py: the probe has no ROOFLINE line for {threads} threads")
    pk = peaks[threads]
    peakF, scalarF, bw = pk["gflops"], pk["gflops1"], pk["triadWAGBs"]
    ridge = peakF / bw
    print(f"Peaks ({threads} threads): {peakF:.1f} GFLOP/s ({int(pk['lanes'])}-wide FMA), "
          f"{scalarF:.1f} GFLOP/s scalar FMA, {bw:.1f} GB/s (triad + write-allocate); "
          f"ridge {ridge:.2f} FLOP/byte")
    print("| case | phase | ns / p-step | FLOP/byte | GFLOP/s | % vector peak | GB/s | % bandwidth |"
          " % of roof |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|")
    points = []
    for name, r in runs:
        model = phase_model(**CASES[name])
        psteps = r["steps"] * r["particles"]
        for ph in PHASES:
            f, b = model[ph]
            t = r["times"][ph]
            gf = f * psteps / t / 1e9
            gb = b * psteps / t / 1e9
            ai = f / b
            roof = min(peakF, ai * bw)
            print(f"| {name} | {ph} | {1e9 * t / psteps:.1f} | {ai:.2f} | {gf:.2f} | "
                  f"{100 * gf / peakF:.1f} | {gb:.1f} | {100 * gb / bw:.0f} | {100 * gf / roof:.0f} |")
            points.append((name, ph, ai, gf))
    if a.out:
        plot(points, peakF, scalarF, bw, threads, a.out, a.title)
        print(f"wrote {a.out}")


def plot(points, peakF, scalarF, bw, threads, out, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7.5, 5.2))
    lo, hi = 0.02, 50.0
    xs = [lo * (hi / lo) ** (k / 400) for k in range(401)]
    ax.plot(xs, [min(peakF, x * bw) for x in xs], "k-", lw=2,
            label=f"roof: {peakF:.0f} GFLOP/s vector FMA, {bw:.0f} GB/s")
    ax.plot(xs, [min(scalarF, x * bw) for x in xs], "k--", lw=1,
            label=f"scalar FMA ceiling {scalarF:.0f} GFLOP/s")
    colours = {"sort": "tab:gray", "P2G": "tab:red", "grid": "tab:green", "G2P": "tab:blue",
               "constitutive": "tab:purple"}
    markers = {"block3D": "o", "block3DPlastic": "s", "block3DViscoelastic": "D", "block2D": "^"}
    for name, ph, ai, gf in points:
        ax.plot(ai, gf, markers.get(name, "x"), color=colours[ph], ms=8, mec="k", mew=0.5)
    handles = [plt.Line2D([], [], ls="", marker="o", color=c, mec="k", mew=0.5, label=p)
               for p, c in colours.items()]
    handles += [plt.Line2D([], [], ls="", marker=m, color="w", mec="k", label=n)
                for n, m in markers.items() if any(p[0] == n for p in points)]
    first = ax.legend(loc="lower right", fontsize=8)
    ax.add_artist(first)
    ax.legend(handles=handles, loc="upper left", fontsize=8, ncol=2)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlim(lo, hi)
    ax.set_ylim(0.05, 2 * peakF)
    ax.set_xlabel("arithmetic intensity [FLOP/byte] (phase model, docs/benchmarks.md)")
    ax.set_ylabel("achieved GFLOP/s (double)")
    ax.set_title(title or f"mpmFoam phases, {threads} threads")
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=130)


if __name__ == "__main__":
    main()
