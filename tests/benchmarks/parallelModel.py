#!/usr/bin/env python3
"""Projected time per step of a large parallel run from this machine's measurements
(docs/parallel.md). Not a test.

    parallelModel.py [--points 1e8] [--cores 32] [--bandwidth 12.5e9] [--latency 2e-6]
                     [--rate 4.9e6] [--out docs/images/parallelModel.png]

Model of one step on N nodes, one rank of `cores` threads per node (hybrid), the points spread
evenly in cube-shaped subdomains of 4³-node blocks (3D, 8 points per cell, USL):
  compute  = (points per rank) / (rate per core × cores × thread efficiency);
  halo     = 2 × ghost blocks × 64 nodes × 104 B / bandwidth + 3 exchanges × 26 neighbours ×
             latency (the sums out, the velocities back: 56 + 48 B per node, measured below);
             ghost blocks of a cube of b blocks per side: (b + 2)³ − b³;
  reduce   = 10 collectives × ⌈log₂ N⌉ × latency (the exchanges go to neighbours only).
The measured inputs (tests/benchmarks/parallel.sh, block3D on 2 ranks): the rate per core
(particle-updates per second of one 1-thread rank, communication excluded), the thread
efficiency of 2 threads, and the halo bytes per step, which the byte model reproduces.
"""
import argparse
import math

import numpy as np

ap = argparse.ArgumentParser()
ap.add_argument("--points", type=float, default=1e8)
ap.add_argument("--cores", type=int, default=32)
ap.add_argument("--bandwidth", type=float, default=12.5e9, help="bytes/s (100 Gb/s)")
ap.add_argument("--latency", type=float, default=2e-6, help="s per message")
ap.add_argument("--rate", type=float, default=4.9e6, help="particle-updates/s of one core")
ap.add_argument("--threads", type=float, default=0.8, help="thread efficiency on a node")
ap.add_argument("--out", default="")
a = ap.parse_args()

BYTES_PER_GHOST_BLOCK = 64 * (56 + 48)  # mass, momentum, force out; v_old, v back


def ghost_blocks(points):
    cells = points / 8.0
    b = cells ** (1.0 / 3.0) / 4.0  # blocks per side of a cubic subdomain
    return (b + 2.0) ** 3 - b ** 3


# Check of the byte model against block3D on 2 ranks: 72 ghost blocks (an 8 x 9 layer of the
# cut plane), measured 468 KiB sent per step by rank 0.
print("byte model: 72 ghost blocks -> %.0f KiB per step (measured 468)"
      % (72 * BYTES_PER_GHOST_BLOCK / 1024))

rows = []
for nodes in [1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048]:
    n = a.points / nodes
    compute = n / (a.rate * a.cores * a.threads)
    g = ghost_blocks(n) if nodes > 1 else 0.0
    halo = (2 * g * BYTES_PER_GHOST_BLOCK / a.bandwidth + 3 * 26 * a.latency) if nodes > 1 else 0.0
    reduce_ = 10 * math.ceil(math.log2(nodes)) * a.latency if nodes > 1 else 0.0
    rows.append((nodes, n, compute, halo, reduce_, compute + halo + reduce_))

t1 = rows[0][5]
print("%6s %12s %10s %10s %10s %10s %8s %12s" % ("nodes", "points/rank", "compute", "halo",
                                                  "reduce", "step", "effic.", "Gupd/s"))
for nodes, n, c, h, r, t in rows:
    print("%6d %12.3g %8.3f ms %8.3f ms %8.3f ms %8.3f ms %7.0f %% %12.3g"
          % (nodes, n, 1e3 * c, 1e3 * h, 1e3 * r, 1e3 * t, 100 * t1 / (nodes * t),
             a.points / t / 1e9))
half = [r for r in rows if t1 / (r[0] * r[5]) < 0.5]
if half:
    print("parallel efficiency falls below 50 %% at %d nodes (%.3g points per node)"
          % (half[0][0], half[0][1]))

if a.out:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    nodes = np.array([r[0] for r in rows])
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    for k, name in ((2, "compute"), (3, "halo"), (4, "collectives"), (5, "step")):
        first = 0 if k in (2, 5) else 1  # one node has no halo and no collectives
        ax.loglog(nodes[first:], [1e3 * r[k] for r in rows[first:]],
                  "o-" if k == 5 else ".--", label=name)
    ax.loglog(nodes, 1e3 * t1 / nodes, "k:", label="ideal")
    ax.axvline(64, color="grey", lw=0.8)
    ax.set_xlabel("nodes (%d cores each, one rank of %d threads)" % (a.cores, a.cores))
    ax.set_ylabel("time per step [ms]")
    ax.set_title("%.0e points, %.0f Gb/s network: projected" % (a.points, a.bandwidth * 8e-9))
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.out, dpi=110)
