#!/usr/bin/env python3
"""Body-phase cost against the number of spheropolygons (issues 10 and 34, docs/benchmarks.md).
Not a test.

    run.py [--counts 500 1000 2000 4000] [--steps 200] [--settle 0.3] [--matrix] [--runs 3]
           [--threads 1] [--solver bin/mpmFoam] [--keep DIR [--reuse]]
    run.py --prepare DIR --count N [--settle 0.3] [--steps 200] [--matrix]

Heap (default): N random pentagons (circumradius 5 mm, sphero-radius 0.5 mm, 2500 kg/m³,
random orientation) on a lattice of pitch 12.5 mm, 10 rows deep and N/10 wide, above a fixed
floor between two fixed walls, fall under gravity into a heap (sdem body–body contact:
k_n = 1e6 N/m, μ = 0.5, restitution 0.5; every body also has the sdem coupling to the MPM
points, a small sand patch far from them). The case is first run for `settle` seconds (written
at the end), then `steps` more steps from that settled state are measured (a restart: the
heap's contact network, not the falling lattice). Δt is a quarter of the contact's stable step
(no sub-steps; at the full step the heap blew up).

Matrix (--matrix): the same lattice, not settled, in sand (Drucker–Prager, h = 5 mm, 2×2 points
a cell, seeded outside the bodies with 1 mm clearance), every body coupled to the points by the
sdem coupling; Δt = 5e-5 s (the sand's CFL step).

For each N it reads the phase table of the median of `runs` runs (by step time: the table's
total less IO and function objects) and prints: ms per step, the "rigid bodies" phase per
step, per body, per Verlet pair and per vertex–edge contact, the point–body coupling
("contact") phase, and the counts: Verlet pairs among the pentagons (bounding circles inflated
by V_d = 0.1 R_min overlap) and touching vertex–edge contacts (the contact history at the start
of the measured steps). The body phase must grow like N (binned neighbour search, O(N log N)
builds), not like N² (every pair). `--prepare` writes one case (settled if not --matrix) into
DIR for tests/benchmarks/run.sh (case `polygonSettling:N` or `polygonSettling:N:matrix`).
"""
import argparse
import math
import os
import random
import re
import shutil
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
R, A, PITCH, ROWS = 0.005, 0.0005, 0.0125, 10
MATRIX_DT, MATRIX_H = 5.0e-5, 0.005


def pentagon(x, y, angle):
    return [[x + R * math.cos(angle + 2 * math.pi * k / 5), y + R * math.sin(angle + 2 * math.pi * k / 5)]
            for k in range(5)]


def heap_dt():
    # A quarter of the law's step [001 Eq. 51] (pentagon mass): a pentagon in a heap has several
    # contacts at its corners (rotational mass ~m/3), and the heap blew up at the full step.
    return 0.25 * 0.1 * 2 * math.pi * math.sqrt(2500 * 2.5 * R * R / 1e6)


def write_control(d, end, dt, write_interval):
    with open(os.path.join(d, "system", "controlDict"), "w") as f:
        f.write("application: mpmFoam\nendTime: %.17g\ndeltaT: %.17g\nadjustTimeStep: no\n"
                "allowUnstableDeltaT: yes\nwriteControl: timeStep\nwriteInterval: %d\n"
                % (end, dt, write_interval))


def write_case(d, n, matrix):
    """The case at t = 0 (controlDict written by the caller)."""
    rows = min(ROWS, n)  # every heap equally deep (contacts per body alike), as wide as N needs
    cols = int(math.ceil(n / rows))
    width, height = cols * PITCH, rows * PITCH
    rng = random.Random(7)
    os.makedirs(os.path.join(d, "system"))
    os.makedirs(os.path.join(d, "constant"))
    with open(os.path.join(d, "system", "mpmSchemes"), "w") as f:
        f.write("kernel: quadraticBSpline\ntransfer: apic\nstressUpdate: USL\n")
    with open(os.path.join(d, "constant", "g"), "w") as f:
        f.write("value: [0, -9.81]\n")
    h = MATRIX_H if matrix else 0.01
    lo = [-0.05, -0.05]
    hi = [lo[0] + h * math.ceil((width + 0.1) / h), lo[1] + h * math.ceil((height + 0.15) / h)]
    with open(os.path.join(d, "constant", "grid"), "w") as f:
        f.write("dimension: 2\nbounds: {min: [%g, %g], max: [%g, %g]}\ncellSize: %g\n"
                "boundary: {yMin: noSlip}\n" % (lo[0], lo[1], hi[0], hi[1], h))
    with open(os.path.join(d, "constant", "materials"), "w") as f:
        f.write("sand: {type: druckerPrager, density: 1500, E: 1.0e6, nu: 0.3, frictionAngle: 30}\n")
    with open(os.path.join(d, "constant", "particles"), "w") as f:
        f.write("patch:\n  material: sand\n  region: {type: box, min: [%g, %g], max: [%g, %g]}\n"
                "  seeding: {method: regular, perDirection: 2}\n"
                % (lo[0] + 0.01, lo[1] + 0.01, lo[0] + 0.03, lo[1] + 0.03))
        if matrix:  # the lattice's voids, between the walls, up to its top row
            f.write("matrix:\n  material: sand\n  region: {type: box, min: [0, 0], max: [%g, %g]}\n"
                    "  seeding: {method: regular, perDirection: 2}\n  outsideBodies: yes\n"
                    "  bodyClearance: 0.001\n" % (width, height))
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
            x = (k % cols + 0.5) * PITCH + rng.uniform(-0.0005, 0.0005)  # no overlap at the start
            y = (k // cols + 0.5) * PITCH
            v = ", ".join("[%.9g, %.9g]" % tuple(p) for p in pentagon(x, y, rng.uniform(0, 2 * math.pi)))
            f.write("p%d:\n  shape: {type: spheropolygon, radius: %g, vertices: [%s]}\n"
                    "  density: 2500\n  coupling: %s\n" % (k, A, v, coupling))


def latest_time(d):
    times = [t for t in os.listdir(d) if re.fullmatch(r"[0-9.e+-]+", t)]
    return max(times, key=float) if times else None


def prepare(d, n, steps, settle, matrix, solver, threads):
    """Write case d for N bodies; settle it (heap); set endTime to `steps` more steps."""
    shutil.rmtree(d, ignore_errors=True)
    write_case(d, n, matrix)
    dt = MATRIX_DT if matrix else heap_dt()
    start = 0.0
    if not matrix and settle > 0:
        k = int(math.ceil(settle / dt))
        write_control(d, k * dt, dt, k)
        with open(os.path.join(d, "log.settle"), "w") as log:
            subprocess.run([solver, "-case", d, "-noFunctionObjects"], stdout=log, stderr=log,
                           check=True, env=dict(os.environ, OMP_NUM_THREADS=str(threads)))
        start = float(latest_time(d))
    write_control(d, start + (steps + 0.5) * dt, dt, 10 ** 9)


def counts(d, n):
    """(Verlet pairs, touching body pairs, vertex–edge contacts) of the latest time of d."""
    t = latest_time(d)
    pos = {}
    if t and os.path.exists(os.path.join(d, t, "uniform", "rigidBodies")):
        name = None
        for line in open(os.path.join(d, t, "uniform", "rigidBodies")):
            m = re.match(r'"?(\w+)"?:\s*$', line)
            if m:
                name = m.group(1)
            m = re.match(r"\s+position:\s*\[([^,]+),\s*([^\]]+)\]", line)
            if m and name and name.startswith("p"):
                pos[int(name[1:])] = (float(m.group(1)), float(m.group(2)))
    contacts, touching = 0, set()
    hist = os.path.join(d, t, "uniform", "bodyContacts") if t else ""
    if os.path.exists(hist):
        rows = re.findall(r"\[(\d+), (\d+), \d+, \d+,", open(hist).read())
        contacts = len(rows)
        touching = {tuple(sorted(r)) for r in rows}
    # Verlet pairs among the pentagons (bounding radius R + a; V_d = 0.1 R_min) by binning,
    # plus the floor and walls against the bodies they reach.
    reach = 2 * (R + A) + 0.1 * (R + A)
    cells = {}
    for k, (x, y) in pos.items():
        cells.setdefault((int(x // reach), int(y // reach)), []).append(k)
    pairs = 0
    for (cx, cy), ks in cells.items():
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for j in cells.get((cx + dx, cy + dy), []):
                    for i in ks:
                        if i < j and (pos[i][0] - pos[j][0]) ** 2 + (pos[i][1] - pos[j][1]) ** 2 < reach ** 2:
                            pairs += 1
    return pairs, len(touching), contacts


def phase_table(log):
    text = open(log).read()
    m = re.search(r"Phase timing \((\d+) steps, (\d+) particles", text)
    times = dict((k.strip(), float(v)) for k, v in re.findall(r"^\s{4}(\S[\w ]*?)\s+([0-9.]+) s ", text, re.M))
    return int(m.group(1)), int(m.group(2)), times


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--counts", type=int, nargs="+", default=[500, 1000, 2000, 4000])
    ap.add_argument("--steps", type=int, default=200)
    ap.add_argument("--settle", type=float, default=0.3, help="seconds of settling (heap)")
    ap.add_argument("--matrix", action="store_true")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--solver", default=os.path.join(ROOT, "bin", "mpmFoam"))
    ap.add_argument("--keep", default="")
    ap.add_argument("--reuse", action="store_true", help="use the cases already prepared in --keep")
    ap.add_argument("--prepare", metavar="DIR")
    ap.add_argument("--count", type=int)
    a = ap.parse_args()
    if a.prepare:
        if not a.count:
            ap.error("--prepare needs --count N")
        prepare(a.prepare, a.count, a.steps, a.settle, a.matrix, a.solver, a.threads)
        return
    work = a.keep or tempfile.mkdtemp()
    print("# %s, %d threads, load average %s" % ("matrix" if a.matrix else "settled heap",
                                                  a.threads, open("/proc/loadavg").read().split()[:3]))
    print("%6s %7s %6s %6s %8s %9s %9s %9s %9s %9s %7s %7s" % (
        "bodies", "points", "pairs", "v-e", "ms/step", "body ms", "us/body", "ns/pair", "ns/v-e",
        "coupl ms", "body %", "coupl %"))
    results = []
    for n in a.counts:
        d = os.path.join(work, "N%d" % n)
        if not (a.reuse and os.path.isdir(d)):
            prepare(d, n, a.steps, a.settle, a.matrix, a.solver, a.threads)
        pairs, touching, contacts = counts(d, n)
        runs = []
        for r in range(a.runs):
            rd = os.path.join(work, "N%d.run" % n)
            shutil.rmtree(rd, ignore_errors=True)
            shutil.copytree(d, rd)
            log = os.path.join(work, "N%d.r%d.log" % (n, r))
            with open(log, "w") as f:
                subprocess.run([a.solver, "-case", rd, "-noFunctionObjects"], stdout=f, stderr=f,
                               check=True, env=dict(os.environ, OMP_NUM_THREADS=str(a.threads)))
            steps, points, times = phase_table(log)
            step = times["total"] - times.get("IO", 0.0) - times.get("functions", 0.0)
            runs.append((step, steps, points, times, log))
            shutil.rmtree(rd)
        runs.sort(key=lambda x: x[0])
        total, steps, points, times, log = runs[(len(runs) - 1) // 2]
        body = times["rigid bodies"] / steps
        coupl = times.get("contact", 0.0) / steps
        results.append((n, body / (n + 3)))
        print("%6d %7d %6d %6d %8.3f %9.3f %9.3f %9.1f %9.1f %9.3f %6.1f%% %6.1f%%" % (
            n, points, pairs, contacts, 1e3 * total / steps, 1e3 * body, 1e6 * body / (n + 3),
            1e9 * body / max(pairs, 1), 1e9 * body / max(contacts, 1), 1e3 * coupl,
            100 * times["rigid bodies"] / total, 100 * times.get("contact", 0.0) / total))
        print("   phases [ms/step]: " + ", ".join("%s %.3f" % (k, 1e3 * v / steps) for k, v in times.items()
                                                if k not in ("total", "functions")))
        print("RESULT bodies=%d points=%d steps=%d pairs=%d touchingPairs=%d contacts=%d step_s=%.4f "
              "bodies_s=%.4f contact_s=%.4f spread=%.4f-%.4f log=%s" % (
                  n, points, steps, pairs, touching, contacts, total, times["rigid bodies"],
                  times.get("contact", 0.0), runs[0][0], runs[-1][0], log))
        sys.stdout.flush()
    for (n0, p0), (n1, p1) in zip(results, results[1:]):
        print("N %d -> %d: body phase per body-step x %.2f (1 for O(N), %.1f for O(N^2))"
              % (n0, n1, p1 / p0, n1 / n0))
    if not a.keep:
        shutil.rmtree(work)


if __name__ == "__main__":
    main()
