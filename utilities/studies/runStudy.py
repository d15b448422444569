#!/usr/bin/python3
"""Small parameter-study runner for mpmFoam cases.

A study is a list of variants of one base case; each variant is a list of overrides
(file, YAML key path, value), e.g. ("constant/materials", "sand.frictionAngle", 34).
For every variant the runner

  1. copies the base case (its input files only) to runs/<study>/<variant>/,
  2. applies the overrides (the YAML file is loaded and regenerated; its leading comment
     block is kept and the applied overrides are listed in a comment),
  3. runs mpmFoam there (OMP_NUM_THREADS=2 unless set; stdout -> log.mpmFoam,
     stderr -> log.stderr), one run at a time,
  4. collects: exit code, the stop message on failure (the FATAL ERROR block of stderr),
     peak loadAverage and its time, final and maximum depth/D, the smallest contact gap,
     wall time, particle-updates per second, the number of particles, and from the
     written particles.vtu files: NaN anywhere, and the splash (points above the initial
     surface + 1 cm) at each write,
  5. writes runs/<study>/<variant>/result.json; the study's results go to
     runs/<study>/results.json.

A variant whose result.json exists is skipped (a study can be resumed); a variant directory
without one (an interrupted run) is removed and run again. A variant identical to one already
run in another study (same base, same overrides) is not run again: its directory becomes a
symbolic link to that run.

Usage:
  runStudy.py STUDY [STUDY ...]    run the studies defined in studies.py (then their checks)
  runStudy.py --list               list the studies and their variants
  runStudy.py --base CASE --study NAME --variant NAME [--set FILE:KEY=VALUE ...]
                                   run one ad-hoc variant (VALUE is parsed as YAML)
Exit code: 0, or 1 when a study's check finds a violation of a hard property.
"""
import argparse
import glob
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import time

import numpy as np
import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
RUNS = os.path.join(HERE, "runs")
SOLVER = os.path.join(ROOT, "bin", "mpmFoam")
INPUTS = ("system", "constant")          # what is copied from the base case
SPLASH_HEIGHT = 0.01                     # m above the initial surface

_NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")


# --------------------------------------------------------------------------- YAML editing
def _numbers(node):
    """PyYAML (YAML 1.1) reads 1e5 as a string; mpmFoam (yaml-cpp) reads it as a number."""
    if isinstance(node, dict):
        return {k: _numbers(v) for k, v in node.items()}
    if isinstance(node, list):
        return [_numbers(v) for v in node]
    if isinstance(node, str) and _NUMBER.match(node):
        return float(node)
    return node


def set_key(data, path, value):
    keys = path.split(".")
    node = data
    for k in keys[:-1]:
        if not isinstance(node.get(k), dict):
            node[k] = {}
        node = node[k]
    node[keys[-1]] = value


def get_key(data, path, default=None):
    node = data
    for k in path.split("."):
        if not isinstance(node, dict) or k not in node:
            return default
        node = node[k]
    return node


def read_yaml(path):
    with open(path) as f:
        return _numbers(yaml.safe_load(f) or {})


def apply_overrides(case, overrides):
    by_file = {}
    for fname, key, value in overrides:
        by_file.setdefault(fname, []).append((key, value))
    for fname, items in by_file.items():
        path = os.path.join(case, fname)
        text = open(path).read() if os.path.exists(path) else ""
        header = []
        for line in text.splitlines():
            if line.startswith("#"):
                header.append(line)
            else:
                break
        data = _numbers(yaml.safe_load(text) or {})
        for key, value in items:
            set_key(data, key, value)
        body = yaml.safe_dump(data, sort_keys=False, default_flow_style=None, width=100)
        note = ["# runStudy.py overrides: " + ", ".join(f"{k} = {json.dumps(v)}" for k, v in items)]
        with open(path, "w") as f:
            f.write("\n".join(header + note) + "\n" + body)


# --------------------------------------------------------------------------- results
def load_dat(case, name):
    files = sorted(glob.glob(os.path.join(case, "postProcessing", name, "*", name + ".dat")),
                   key=lambda f: float(f.split(os.sep)[-2]))
    rows = [np.loadtxt(f, comments="#", ndmin=2) for f in files if os.path.getsize(f) > 0]
    rows = [r for r in rows if r.size]
    return np.vstack(rows) if rows else np.zeros((0, 8))


def time_dirs(case):
    out = []
    for d in os.listdir(case):
        try:
            t = float(d)
        except ValueError:
            continue
        if os.path.exists(os.path.join(case, d, "particles.vtu")):
            out.append((t, d))
    return sorted(out)


def read_vtu(path):
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    g = r.GetOutput()
    pts = vtk_to_numpy(g.GetPoints().GetData()) if g.GetPoints() else np.zeros((0, 3))
    arrays = {}
    pd = g.GetPointData()
    for i in range(pd.GetNumberOfArrays()):
        arrays[pd.GetArrayName(i)] = vtk_to_numpy(pd.GetArray(i))
    return pts, arrays


def analyse_vtu(case, surface, axis_xy, prune=True):
    """NaN check of every written particles.vtu, and the splash at each write."""
    splash, nan_dirs = [], []
    for t, d in time_dirs(case):
        pts, arrays = read_vtu(os.path.join(case, d, "particles.vtu"))
        finite = np.isfinite(pts).all() and all(
            np.isfinite(a).all() for a in arrays.values() if np.issubdtype(a.dtype, np.floating))
        if not finite:
            nan_dirs.append(d)
        z = pts[:, 2]
        up = np.isfinite(z) & (z > surface + SPLASH_HEIGHT)
        r = np.hypot(pts[up, 0] - axis_xy[0], pts[up, 1] - axis_xy[1])
        splash.append({"time": t, "dir": d, "count": int(up.sum()),
                       "radius95": float(np.percentile(r, 95)) if r.size else 0.0,
                       "height": float(z[up].max() - surface) if up.any() else 0.0})
    peak = max(splash, key=lambda s: s["count"]) if splash else None
    if prune and splash:   # keep the first, the last, the splash peak and any non-finite write
        keep = {splash[0]["dir"], splash[-1]["dir"], peak["dir"]} | set(nan_dirs)
        for s in splash:
            if s["dir"] not in keep:
                shutil.rmtree(os.path.join(case, s["dir"]), ignore_errors=True)
    return splash, peak, nan_dirs


def stop_message(stderr):
    m = re.search(r"--> MPMFOAM FATAL.*?(?=\nMPMFOAM exiting|\Z)", stderr, re.S)
    if m:
        return " ".join(m.group(0).split())
    lines = [l for l in stderr.strip().splitlines() if l.strip()]
    return " ".join(lines[-3:]) if lines else ""


def collect(case, rc, wall):
    log = open(os.path.join(case, "log.mpmFoam"), errors="replace").read()
    err = open(os.path.join(case, "log.stderr"), errors="replace").read()
    res = {"exitCode": rc, "wallTimePython": wall}
    res["stopMessage"] = stop_message(err) if rc != 0 else ""
    res["warnings"] = sorted(set(" ".join(w.split()) for w in
                                 re.findall(r"--> MPMFOAM Warning.*?(?:\n\n|\Z)", err, re.S)))
    m = re.search(r"with (\d+) particles", log)
    res["particles"] = int(m.group(1)) if m else None
    m = re.findall(r"Particle-updates per second: (\S+)", log)
    res["particleUpdatesPerSecond"] = float(m[-1]) if m else None
    m = re.findall(r"^\s*total\s+(\S+) s", log, re.M)
    res["wallTime"] = float(m[-1]) if m else wall

    ctrl = read_yaml(os.path.join(case, "system", "controlDict"))
    res["endTime"] = ctrl.get("endTime")
    cell, depth, gap = load_dat(case, "loadCell"), load_dat(case, "depth"), load_dat(case, "gap")
    res["lastTime"] = float(depth[-1, 0]) if len(depth) else 0.0
    res["deltaT"] = float(ctrl["deltaT"])
    # a fixed step ends the run within half a step of endTime (docs/caseFormat.md §2)
    res["reachedEnd"] = rc == 0 and \
        res["lastTime"] >= float(ctrl["endTime"]) - 0.5 * res["deltaT"] - 1e-12
    if len(cell):
        i = int(np.nanargmax(cell[:, 2]))
        res["peakLoadAverage"] = float(cell[i, 2])
        res["peakLoadTime"] = float(cell[i, 0])
        res["peakLoadRaw"] = float(np.nanmax(cell[:, 1]))
    if len(depth):
        res["finalDepthOverD"] = float(depth[-1, 2])
        res["maxDepthOverD"] = float(np.nanmax(depth[:, 2]))
    if len(gap):
        res["smallestGap"] = float(np.nanmin(gap[:, 1:3]))
        res["maxPenetration"] = max(0.0, -res["smallestGap"])

    surface = get_key(ctrl, "functions.depth.surface", 0.08)
    bodies = read_yaml(os.path.join(case, "constant", "rigidBodies"))
    pos = next(iter(bodies.values()))["position"] if bodies else [0, 0, 0]
    splash, peak, nan_dirs = analyse_vtu(case, float(surface), pos[:2])
    res["nanWritten"] = bool(nan_dirs)
    res["nanDirs"] = nan_dirs
    res["splash"] = splash
    if peak:
        res["splashPeakCount"] = peak["count"]
        res["splashPeakTime"] = peak["time"]
        res["splashPeakRadius95"] = peak["radius95"]
    return res


# --------------------------------------------------------------------------- running
def variant_key(base, overrides):
    canon = json.dumps([os.path.relpath(os.path.abspath(base), ROOT),
                        sorted([list(o) for o in overrides], key=lambda o: (o[0], o[1]))],
                       sort_keys=True)
    return hashlib.sha1(canon.encode()).hexdigest()[:16]


def _index():
    path = os.path.join(RUNS, "_index.json")
    return json.load(open(path)) if os.path.exists(path) else {}


def _save_index(index):
    path = os.path.join(RUNS, "_index.json")
    with open(path + ".tmp", "w") as f:
        json.dump(index, f, indent=1, sort_keys=True)
    os.replace(path + ".tmp", path)


def run_variant(study, name, base, overrides, log=print, run=True):
    """Run one variant (or reuse its earlier result); with run=False only reuse: None if none."""
    os.makedirs(os.path.join(RUNS, study), exist_ok=True)
    case = os.path.join(RUNS, study, name)
    key = variant_key(base, overrides)
    done = os.path.join(case, "result.json")
    if os.path.exists(done):
        res = json.load(open(done))
        if res.get("key") == key:
            log(f"  {study}/{name}: done before, skipped")
            return res
        log(f"  {study}/{name}: the overrides changed, running again")
    index = _index()
    other = index.get(key)
    have_other = other and other != f"{study}/{name}" and \
        os.path.exists(os.path.join(RUNS, other, "result.json"))
    if not run and not have_other:
        return None
    if os.path.islink(case):
        os.remove(case)
    elif os.path.exists(case):
        shutil.rmtree(case)
    if have_other:
        os.symlink(os.path.join("..", other), case)
        log(f"  {study}/{name}: same case as {other}, linked")
        return json.load(open(done))

    os.makedirs(case)
    for d in INPUTS:
        shutil.copytree(os.path.join(base, d), os.path.join(case, d))
    apply_overrides(case, overrides)
    env = dict(os.environ)
    env.setdefault("OMP_NUM_THREADS", "2")
    env.setdefault("OMP_WAIT_POLICY", "passive")   # the machine is shared: no spin-waiting
    log(f"  {study}/{name}: running ...", end="", flush=True)
    t0 = time.time()
    with open(os.path.join(case, "log.mpmFoam"), "w") as out, \
            open(os.path.join(case, "log.stderr"), "w") as err:
        rc = subprocess.call([SOLVER, "-case", case], stdout=out, stderr=err, env=env)
    wall = time.time() - t0
    res = collect(case, rc, wall)
    res.update({"study": study, "variant": name, "key": key,
                "base": os.path.relpath(os.path.abspath(base), ROOT),
                "overrides": [list(o) for o in overrides]})
    with open(done, "w") as f:
        json.dump(res, f, indent=1)
    index[key] = f"{study}/{name}"
    _save_index(index)
    log(f" exit {rc}, {wall:.0f} s"
        + (f", peak {res.get('peakLoadAverage', float('nan')):.1f} N,"
           f" depth/D {res.get('finalDepthOverD', float('nan')):.3f}" if "peakLoadAverage" in res else "")
        + (f"  STOP: {res['stopMessage'][:160]}" if rc else ""))
    return res


def run_study(study, spec, log=print, only=None):
    """Run the variants of a study (only: the names to run; the others are taken if they
    were run before, else left out) and write runs/<study>/results.json."""
    log(f"study {study}: {len(spec['variants'])} variants (base {spec['base']})")
    results = {"study": study, "base": spec["base"], "variants": {}}
    for v in spec["variants"]:
        overrides = list(spec.get("common", [])) + list(v["overrides"])
        res = run_variant(study, v["name"], os.path.join(ROOT, spec["base"]), overrides, log,
                          run=only is None or v["name"] in only)
        if res is None:
            log(f"  {study}/{v['name']}: not run (left out)")
            continue
        results["variants"][v["name"]] = {"params": v.get("params", {}), "result": res}
    path = os.path.join(RUNS, study, "results.json")
    with open(path, "w") as f:
        json.dump(results, f, indent=1)
    return results


def load_results(study):
    path = os.path.join(RUNS, study, "results.json")
    return json.load(open(path)) if os.path.exists(path) else None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("studies", nargs="*")
    ap.add_argument("--list", action="store_true")
    ap.add_argument("--only", help="comma-separated variants to run (others: reused if run before)")
    ap.add_argument("--base")
    ap.add_argument("--study")
    ap.add_argument("--variant")
    ap.add_argument("--set", action="append", default=[], metavar="FILE:KEY=VALUE")
    a = ap.parse_args()
    if a.base:
        overrides = []
        for s in a.set:
            fk, value = s.split("=", 1)
            fname, key = fk.split(":", 1)
            overrides.append((fname, key, _numbers(yaml.safe_load(value))))
        res = run_variant(a.study or "adhoc", a.variant or "run", os.path.abspath(a.base), overrides)
        return 0 if res["exitCode"] == 0 else 1
    sys.path.insert(0, HERE)
    import studies as S
    if a.list or not a.studies:
        for name, spec in S.STUDIES.items():
            print(f"{name}: " + ", ".join(v["name"] for v in spec["variants"]))
        return 0
    status = 0
    for name in a.studies:
        results = run_study(name, S.STUDIES[name],
                            only=a.only.split(",") if a.only else None)
        for label, state, detail in S.check(name, results):
            print(f"  [{state}] {label}: {detail}")
            if state == "VIOLATION":
                status = 1
    return status


if __name__ == "__main__":
    sys.exit(main())
