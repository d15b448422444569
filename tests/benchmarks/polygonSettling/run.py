#!/usr/bin/env python3
"""Body-phase cost against the number of spheropolygons (issue 10, docs/benchmarks.md). Not a test.

    run.py [--counts 100 1000 10000] [--steps 200] [--solver bin/mpmFoam] [--keep DIR]

For each count N a 2D case is written: N random pentagons (circumradius 5 mm, sphero-radius
0.5 mm, 2500 kg/m³, random orientation) on a lattice of pitch 12.5 mm above a fixed floor between
two fixed walls, falling under gravity into a heap (sdem body–body contact: k_n = 1e6 N/m,
μ = 0.5, restitution 0.5), and a small sand patch for the MPM part. It runs `steps` steps at the
contact's stable Δt (no sub-steps) with -noFunctionObjects and reads the phase table: the
"rigid bodies" phase per step and per body. The body phase must grow like N (binned neighbour
search, O(N log N) builds), not like N² (every pair).
"""
import argparse
import math
import os
import random
import re
import shutil
import subprocess
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
R, A, PITCH = 0.005, 0.0005, 0.0125


def pentagon(x, y, angle):
    return [[x + R * math.cos(angle + 2 * math.pi * k / 5), y + R * math.sin(angle + 2 * math.pi * k / 5)]
            for k in range(5)]


def write_case(d, n, steps):
    cols = max(4, int(math.ceil(math.sqrt(4 * n))))  # a heap four times as wide as tall
    rows = int(math.ceil(n / cols))
    width, height = cols * PITCH, rows * PITCH
    rng = random.Random(7)
    os.makedirs(os.path.join(d, "system"))
    os.makedirs(os.path.join(d, "constant"))
    dt = 0.1 * 2 * math.pi * math.sqrt(2500 * 2.5 * R * R / 1e6)  # [001 Eq. 51], pentagon mass
    with open(os.path.join(d, "system", "controlDict"), "w") as f:
        f.write("application: mpmFoam\nendTime: %.17g\ndeltaT: %.17g\nadjustTimeStep: no\n"
                "allowUnstableDeltaT: yes\nwriteControl: timeStep\nwriteInterval: 1000000\n"
                % (steps * dt, dt))
    with open(os.path.join(d, "system", "mpmSchemes"), "w") as f:
        f.write("kernel: quadraticBSpline\ntransfer: apic\nstressUpdate: USL\n")
    with open(os.path.join(d, "constant", "g"), "w") as f:
        f.write("value: [0, -9.81]\n")
    lo = [-0.05, -0.05]
    hi = [lo[0] + 0.01 * math.ceil((width + 0.1) / 0.01), lo[1] + 0.01 * math.ceil((height + 0.15) / 0.01)]
    with open(os.path.join(d, "constant", "grid"), "w") as f:
        f.write("dimension: 2\nbounds: {min: [%g, %g], max: [%g, %g]}\ncellSize: 0.01\n"
                "boundary: {yMin: noSlip}\n" % (lo[0], lo[1], hi[0], hi[1]))
    with open(os.path.join(d, "constant", "materials"), "w") as f:
        f.write("sand: {type: druckerPrager, density: 1500, E: 1.0e6, nu: 0.3, frictionAngle: 30}\n")
    with open(os.path.join(d, "constant", "particles"), "w") as f:
        f.write("patch:\n  material: sand\n  region: {type: box, min: [%g, %g], max: [%g, %g]}\n"
                "  seeding: {method: regular, perDirection: 2}\n"
                % (lo[0] + 0.01, lo[1] + 0.01, lo[0] + 0.03, lo[1] + 0.03))
    with open(os.path.join(d, "constant", "bodyContact"), "w") as f:
        f.write("type: sdem\nkn: 1.0e6\nfriction: 0.5\nrestitution: 0.5\n")
    coupling = "{type: sdem, kn: 1.0e5, friction: 0.3, radius: 0.002, verletDistance: 0.002}"
    with open(os.path.join(d, "constant", "rigidBodies"), "w") as f:
        def wall(name, x0, y0, x1, y1):
            f.write("%s:\n  shape: {type: spheropolygon, radius: %g, vertices: [[%g, %g], [%g, %g], "
                    "[%g, %g], [%g, %g]]}\n  density: 2500\n  motion: fixed\n  coupling: %s\n"
                    % (name, A, x0, y0, x1, y0, x1, y1, x0, y1, coupling))
        wall("floor", -0.02, -0.02, width + 0.02, -0.001)
        wall("left", -0.02, -0.001, -0.001, height + 0.05)
        wall("right", width + 0.001, -0.001, width + 0.02, height + 0.05)
        for k in range(n):
            x = (k % cols + 0.5) * PITCH + rng.uniform(-0.001, 0.001)
            y = (k // cols + 0.5) * PITCH
            v = ", ".join("[%.9g, %.9g]" % tuple(p) for p in pentagon(x, y, rng.uniform(0, 2 * math.pi)))
            f.write("p%d:\n  shape: {type: spheropolygon, radius: %g, vertices: [%s]}\n"
                    "  density: 2500\n  coupling: %s\n" % (k, A, v, coupling))


def body_phase(log):
    text = open(log).read()
    steps = int(re.search(r"Phase timing \((\d+) steps", text).group(1))
    bodies = float(re.search(r"rigid bodies\s+([0-9.]+) s", text).group(1))
    total = float(re.search(r"^\s+total\s+([0-9.]+) s", text, re.M).group(1))
    return steps, bodies, total


ap = argparse.ArgumentParser()
ap.add_argument("--counts", type=int, nargs="+", default=[100, 1000, 10000])
ap.add_argument("--steps", type=int, default=200)
ap.add_argument("--solver", default=os.path.join(ROOT, "bin", "mpmFoam"))
ap.add_argument("--keep", default="")
a = ap.parse_args()
work = a.keep or tempfile.mkdtemp()
print("%8s %8s %14s %16s %10s" % ("bodies", "steps", "body phase", "per body-step", "of step"))
results = []
for n in a.counts:
    d = os.path.join(work, "N%d" % n)
    shutil.rmtree(d, ignore_errors=True)
    write_case(d, n, a.steps)
    with open(os.path.join(d, "log"), "w") as log:
        subprocess.run([a.solver, "-case", d, "-noFunctionObjects"], stdout=log, stderr=log,
                       check=True, env=dict(os.environ, OMP_NUM_THREADS="1"))
    steps, bodies, total = body_phase(os.path.join(d, "log"))
    per = bodies / steps / (n + 3)
    results.append((n, per))
    print("%8d %8d %12.3f s %13.3f us %9.1f %%" % (n, steps, bodies, 1e6 * per, 100 * bodies / total))
for (n0, p0), (n1, p1) in zip(results, results[1:]):
    print("N %d -> %d: cost per body-step x %.2f (constant for O(N), x %d for O(N^2))"
          % (n0, n1, p1 / p0, n1 // n0))
if not a.keep:
    shutil.rmtree(work)
