"""Time series and derived numbers of the study runs (shared by studies.py and report.py)."""
import os

import numpy as np

from runStudy import RUNS, load_dat

T_COMPARE = 0.06   # s: the resolution study compares at the end of the h = 3 mm run


def series(results):
    out = {}
    for name in results["variants"]:
        case = os.path.join(RUNS, results["study"], name)
        out[name] = {"load": load_dat(case, "loadCell"), "depth": load_dat(case, "depth"),
                     "gap": load_dat(case, "gap")}
    return out


def value_at(a, col, t, tol=1e-9):
    """Column col of series a linearly interpolated at time t (None if it ends more than tol
    before t; within tol the last value is taken)."""
    if len(a) == 0 or a[-1, 0] < t - tol:
        return None
    return float(np.interp(t, a[:, 0], a[:, col]))


def peak_until(a, col, t):
    m = a[:, 0] <= t + 1e-12
    i = int(np.argmax(a[m, col]))
    return float(a[m, col][i]), float(a[m, 0][i])


def resolution_errors(results, ser, ref="h3", t=T_COMPARE):
    """Relative errors of the peak load (t <= T) and of depth/D at T against the h = 3 mm run;
    the wall time is scaled to T of simulated time."""
    if ref not in ser:
        return {}
    pr, _ = peak_until(ser[ref]["load"], 2, t)
    dr = value_at(ser[ref]["depth"], 2, t)
    out = {}
    for name, s in ser.items():
        r = results["variants"][name]["result"]
        p, _ = peak_until(s["load"], 2, t)
        d = value_at(s["depth"], 2, t)
        if d is None:
            continue
        out[name] = {"peak": abs(p - pr) / pr, "depth": abs(d - dr) / dr, "peakValue": p,
                     "depthValue": d, "wall": r["wallTime"] * t / r["lastTime"],
                     "particles": r["particles"], "pups": r["particleUpdatesPerSecond"]}
    return out
