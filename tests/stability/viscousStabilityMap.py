#!/usr/bin/python3
"""Stability map of the viscous time-step limit [002 Eq. 79] (issue 9, item 4).

A glass block (viscoelasticMuI, tests/cases/viscousStability2D) confined in a no-slip box
under 100 kPa of isotropic pressure rings from an initial axial mode (0.05 m/s) for a fixed
number of steps at a fixed Δt = r Δt_cr, with Δt_cr the limit the solver reports ("Stable
deltaT" in its log: h/(c + |v|) (√(ϑ̂² + 1) − ϑ̂)), for e ∈ {1, 0.01, 0.001} and r from 0.25 to
4; linear kernel, USF, pure FLIP (the paper's scheme). Each run is

  stable    it completes and every written particles.vtu is finite, with |v| ≤ 0.1 m/s (twice
            the initial amplitude) and the pressure within 10 % of 100 kPa everywhere;
  stopped   mpmFoam exits non-zero with a FATAL ERROR naming the step, phase and particle,
            and every particles.vtu it wrote is finite;
  garbage   anything else: non-finite or absurd output, or a crash without the message.

The test fails if a run at r ≤ 1 is not stable (the limit must be sufficient) or a run at
r ≤ 2 is garbage (the issue's range). Beyond r = 2 the outcome is reported, not asserted
(docs/viscoelastic.md). Writes stabilityMap.txt and stabilityMap.png to --out.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

ROOT = os.environ.get("MPMFOAM_DIR") or os.path.abspath(os.path.join(os.path.dirname(__file__), "../.."))
SOLVER = os.path.join(ROOT, "bin", "mpmFoam")
TEMPLATE = os.path.join(ROOT, "tests", "cases", "viscousStability2D")
RATIOS = [0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 2.0, 3.0, 4.0]
RESTITUTIONS = [1.0, 0.01, 0.001]
STEPS = 3000


def set_key(path, key, value):
    with open(path) as f:
        text = f.read()
    text, n = re.subn(rf"^(\s*){key}:.*$", rf"\g<1>{key}: {value}", text, flags=re.M)
    if n == 0:
        text += f"{key}: {value}\n"
    with open(path, "w") as f:
        f.write(text)


def run(case, args=()):
    env = dict(os.environ, OMP_NUM_THREADS=os.environ.get("OMP_NUM_THREADS", "2"))
    return subprocess.run([SOLVER, "-case", case, *args], capture_output=True, text=True, env=env)


def outputs_sane(case):
    """(all finite, largest |v|, pressure range) over every written particles.vtu."""
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy

    finite, vmax, pmin, pmax = True, 0.0, np.inf, -np.inf
    for d in os.listdir(case):
        f = os.path.join(case, d, "particles.vtu")
        if not os.path.isfile(f):
            continue
        r = vtk.vtkXMLUnstructuredGridReader()
        r.SetFileName(f)
        r.Update()
        out = r.GetOutput()
        pd = out.GetPointData()
        arrays = [vtk_to_numpy(out.GetPoints().GetData())]
        arrays += [vtk_to_numpy(pd.GetArray(i)) for i in range(pd.GetNumberOfArrays())]
        finite &= all(np.isfinite(a).all() for a in arrays)
        v = vtk_to_numpy(pd.GetArray("velocity"))
        vmax = max(vmax, float(np.abs(v).max()) if v.size else 0.0)
        p = vtk_to_numpy(pd.GetArray("pressure"))
        pmin, pmax = min(pmin, float(p.min())), max(pmax, float(p.max()))
    return finite, vmax, pmin, pmax


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default="stabilityMap")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    work = tempfile.mkdtemp(prefix="mpmFoam_stability_")
    rows, failures = [], []
    try:
        for e in RESTITUTIONS:
            base = os.path.join(work, f"e{e}")
            shutil.copytree(TEMPLATE, base)
            set_key(os.path.join(base, "constant", "materials"), "restitution", e)
            dry = run(base, ["-dry-run"])
            m = re.search(r"Stable deltaT: (\S+) s", dry.stdout)
            if dry.returncode != 0 or not m:
                sys.exit(f"dry run failed for e = {e}:\n{dry.stdout}\n{dry.stderr}")
            dtcr = float(m.group(1))
            for r in RATIOS:
                case = os.path.join(work, f"e{e}_r{r}")
                shutil.copytree(TEMPLATE, case)
                set_key(os.path.join(case, "constant", "materials"), "restitution", e)
                ctrl = os.path.join(case, "system", "controlDict")
                dt = r * dtcr
                set_key(ctrl, "deltaT", f"{dt:.12g}")
                set_key(ctrl, "adjustTimeStep", "no")
                set_key(ctrl, "allowUnstableDeltaT", "yes")
                set_key(ctrl, "endTime", f"{STEPS * dt:.12g}")
                t0 = time.time()
                p = run(case)
                wall = time.time() - t0
                finite, vmax, pmin, pmax = outputs_sane(case)
                sane = vmax <= 0.1 and 0.9e5 <= pmin and pmax <= 1.1e5
                detail = f"|v|max {vmax:.3g} m/s, p {pmin / 1e3:.4g}..{pmax / 1e3:.4g} kPa"
                if p.returncode == 0 and finite and sane:
                    outcome, why = "stable", detail
                elif p.returncode != 0 and "FATAL ERROR" in p.stderr and finite:
                    outcome = "stopped"
                    msg = p.stderr.split("FATAL ERROR:")[-1].strip().splitlines()
                    why = msg[0][:110] if msg else ""
                else:
                    outcome, why = "garbage", f"rc {p.returncode}, finite {finite}, {detail}"
                rows.append((e, r, dt, outcome, wall, why))
                print(f"e = {e:<6} r = {r:<5} dt = {dt:.3e} s  {outcome:<8} {wall:6.1f} s  {why}",
                      flush=True)
                if outcome == "garbage" and r <= 2.0:
                    failures.append(f"e = {e}, r = {r}: garbage ({why})")
                elif r <= 1.0 and outcome != "stable":
                    failures.append(f"e = {e}, r = {r}: {outcome} at or below the limit ({why})")
                shutil.rmtree(case)
    finally:
        shutil.rmtree(work, ignore_errors=True)

    with open(os.path.join(args.out, "stabilityMap.txt"), "w") as f:
        f.write("# e  dt/dt_cr  dt[s]  outcome  wall[s]  detail\n")
        for e, r, dt, o, w, why in rows:
            f.write(f"{e} {r} {dt:.4e} {o} {w:.2f} {why}\n")
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        colour = {"stable": "tab:green", "stopped": "tab:orange", "garbage": "tab:red"}
        fig, ax = plt.subplots(figsize=(6, 2.8))
        for k, e in enumerate(RESTITUTIONS):
            for (ee, r, _, o, _, _) in rows:
                if ee == e:
                    ax.scatter(r, k, c=colour[o], s=120, marker="s")
        ax.axvline(1.0, color="k", lw=0.8, ls="--")
        ax.set_yticks(range(len(RESTITUTIONS)), [f"e = {e}" for e in RESTITUTIONS])
        ax.set_xlabel(r"$\Delta t / \Delta t_{cr}$ [002 Eq. 79]")
        ax.set_title("green: stable, orange: stopped with a message, red: garbage", fontsize=9)
        fig.tight_layout()
        fig.savefig(os.path.join(args.out, "stabilityMap.png"), dpi=120)
    except ImportError:
        pass
    if failures:
        print("FAIL:\n  " + "\n  ".join(failures))
        sys.exit(1)
    print(f"viscousStabilityMap: {len(rows)} runs; stable at and below the limit, no garbage up "
          "to twice the limit")


if __name__ == "__main__":
    main()
