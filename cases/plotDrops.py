#!/usr/bin/env python3
"""Impact load and intrusion depth / D against time for the six drop cases [000 §4.3].

Usage: plotDrops.py [root]   (root holds glassDrop20 … steelDrop60 after their Allrun;
default: this folder). Writes dropCases.png and prints a markdown table of peak load, final
depth / D and wall time per case.
"""
import glob
import os
import re
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

root = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
CASES = ["glassDrop20", "glassDrop40", "glassDrop60", "steelDrop20", "steelDrop40", "steelDrop60"]


def load(case, name):
    files = sorted(glob.glob(os.path.join(root, case, "postProcessing", name, "*", name + ".dat")),
                   key=lambda f: float(f.split(os.sep)[-2]))
    if not files:
        return None
    return np.vstack([np.loadtxt(f, comments="#", ndmin=2) for f in files])


fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.2))
rows = []
for case in CASES:
    cell, depth = load(case, "loadCell"), load(case, "depth")
    if cell is None or depth is None:
        continue
    style = "-" if case.startswith("glass") else "--"
    a1.plot(1000 * cell[:, 0], cell[:, 2], style, lw=1, label=case)
    a2.plot(1000 * depth[:, 0], depth[:, 2], style, lw=1.5, label=case)
    log = open(os.path.join(root, case, "log.mpmFoam")).read()
    wall = re.findall(r"total\s+(\S+) s", log)
    pups = re.findall(r"Particle-updates per second: (\S+)", log)
    static = cell[cell[:, 0] > cell[-1, 0] - 0.01, 2].mean()
    k = np.argmax(cell[:, 2])
    rows.append((case, cell[k, 2], 1000 * cell[k, 0], static, depth[:, 2].max(), depth[-1, 2],
                 wall[-1] if wall else "?", pups[-1] if pups else "?"))

a1.set_xlabel("t [ms]")
a1.set_ylabel("load on the bottom, 2 ms moving average [N]")
a1.set_xlim(0, 60)
a1.grid(alpha=0.3)
a1.legend(fontsize=8)
a2.set_xlabel("t [ms]")
a2.set_ylabel("intrusion depth / D")
a2.grid(alpha=0.3)
a2.legend(fontsize=8, loc="lower right")
fig.suptitle("Spheres dropped on loose Toyoura sand (h = 4 mm, FLIP/GIMP, barrier coupling)")
fig.tight_layout()
fig.savefig(os.path.join(root, "dropCases.png"), dpi=110)

print("| case | peak load [N] | at [ms] | static load [N] | max depth/D | final depth/D | wall time [s] | particle-updates/s |")
print("|---|---|---|---|---|---|---|---|")
for r in rows:
    print(f"| {r[0]} | {r[1]:.1f} | {r[2]:.1f} | {r[3]:.1f} | {r[4]:.3f} | {r[5]:.3f} | {r[6]} | {r[7]} |")
