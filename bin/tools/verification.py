"""Checks of the verification tutorials against their analytic answers (numpy and vtk only).

Used by tutorials/verification/*/validate (which print, plot and exit) and by the scheme
matrix (tests/schemeMatrix), which runs the same problems under every scheme:

    import os, sys
    sys.path.insert(0, os.path.join(os.environ["MPMFOAM_DIR"], "bin", "tools"))
    import verification
    r = verification.elastic_column("path/to/case")          # after mpmFoam has run there
    ok = verification.elastic_column_passes(r)                # tutorial tolerances
    a = verification.axial_vibration("path/to/run")

Both return a dict of the measured errors, the case data and the solver's cost
(solver_cost: wall time and particle-updates per second from log.mpmFoam).
"""
import glob
import os
import re

import numpy as np


def read_yaml_scalar(path, key):
    """First 'key: number' in a small YAML file (nested keys allowed)."""
    with open(path) as f:
        for line in f:
            m = re.match(r"\s*" + key + r"\s*:\s*([-+0-9.eE]+)", line.split("#")[0])
            if m:
                return float(m.group(1))
    raise SystemExit(f"validate: no '{key}' in {path}")


def read_vtu(path):
    """(points (n, 3), {point-data name: array}) of a VTK XML unstructured grid."""
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy

    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    out = r.GetOutput()
    pd = out.GetPointData()
    arrays = {pd.GetArrayName(k): vtk_to_numpy(pd.GetArray(k)) for k in range(pd.GetNumberOfArrays())}
    return vtk_to_numpy(out.GetPoints().GetData()), arrays


def time_dirs(case):
    """Sorted [(time, directory name)] of the time directories of `case` with particles.vtu."""
    ts = []
    for d in os.listdir(case):
        try:
            t = float(d)
        except ValueError:
            continue
        if os.path.isfile(os.path.join(case, d, "particles.vtu")):
            ts.append((t, d))
    return sorted(ts)


def solver_cost(log):
    """Cost of a run from its mpmFoam log: dict with wall (phase-table total [s]), pups
    (particle-updates per second), steps, particles, threads and table (the phase table text).
    NaN / 0 / "" where the log lacks them."""
    out = dict(wall=float("nan"), pups=float("nan"), steps=0, particles=0, threads=0, table="")
    if not os.path.isfile(log):
        return out
    text = open(log).read()
    table = re.search(r"(Phase timing.*?)\nParticle-updates", text, re.S)
    total = re.search(r"^\s*total\s+([0-9.eE+-]+) s", text, re.M)
    pups = re.search(r"Particle-updates per second:\s*([0-9.eE+-]+)", text)
    head = re.search(r"Phase timing \((\d+) steps, (\d+) particles, (\d+) threads", text)
    if total:
        out["wall"] = float(total.group(1))
    if pups:
        out["pups"] = float(pups.group(1))
    if head:
        out["steps"], out["particles"], out["threads"] = (int(head.group(k)) for k in (1, 2, 3))
    if table:
        out["table"] = table.group(1)
    return out


# ---- elastic column under its own weight ------------------------------------------------------
# Reference (uniaxial strain: slip side walls, plane strain in 2D):
#     sigma_v(Y0) = -rho g (H - Y0)                       vertical stress [Pa]
#     u(Y0)       = rho g / M (H Y0 - Y0^2 / 2)           settlement (downwards) [m]
#     M           = E (1 - nu) / ((1 + nu)(1 - 2 nu))     constrained modulus [Pa]
# with Y0 each particle's initial height (particles matched by `id` between 0/ and the last
# time directory).

#: Tolerances of the tutorials (GIMP, FLIP 0.99, USL, h = 0.05 m): relative L2 error of
#: sigma_v below the top cell layer, relative error of the top settlement, change of the top
#: settlement between the last two writes, base reaction against the weight.
ELASTIC_COLUMN_TOL = dict(stress=0.03, settle=0.05, static=0.005, reaction=0.01)


def elastic_column(case):
    """Settled elastic column in `case` against 1D theory.

    Returns a dict: dim, h, rho, gmag, M, H, n (particles), t_end, t_prev (times of the last two
    writes), stress_err (relative L2 of sigma_v over `below`), settle_num, settle_ref,
    settle_err (signed, relative), static_change (relative change of the top settlement between
    the last two writes), ke_ratio (kinetic energy at the end / its peak, NaN without
    postProcessing/energy), reaction (base face), weight, reaction_err, reaction_total
    (vertical reaction of all faces), reaction_total_err (NaN without postProcessing/reactions),
    cost (solver_cost), and per-particle arrays Y0, sv, u, below.
    """
    const = os.path.join(case, "constant")
    dim = int(read_yaml_scalar(os.path.join(const, "grid"), "dimension"))
    h = read_yaml_scalar(os.path.join(const, "grid"), "cellSize")
    rho = read_yaml_scalar(os.path.join(const, "materials"), "density")
    E = read_yaml_scalar(os.path.join(const, "materials"), "E")
    nu = read_yaml_scalar(os.path.join(const, "materials"), "nu")
    with open(os.path.join(const, "g")) as f:
        g = np.array([float(v) for v in re.search(r"\[(.*)\]", f.read()).group(1).split(",")])
    gmag = np.linalg.norm(g)
    M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
    up = dim - 1  # vertical axis: y in 2D, z in 3D
    sv_comp = 4 * up  # sigma_yy (4) or sigma_zz (8) in the row-major 9-component stress

    ts = time_dirs(case)
    if len(ts) < 3 or ts[0][0] != 0.0:
        raise SystemExit(f"validate: {case} needs 0/ and two later time directories; run it first")
    x0, a0 = read_vtu(os.path.join(case, ts[0][1], "particles.vtu"))
    x1, a1 = read_vtu(os.path.join(case, ts[-1][1], "particles.vtu"))
    order0 = np.argsort(a0["id"])
    order1 = np.argsort(a1["id"])
    if not np.array_equal(a0["id"][order0], a1["id"][order1]):
        raise SystemExit(f"validate: particle ids differ between 0/ and the last time in {case}")
    Y0 = x0[order0, up]
    Y1 = x1[order1, up]
    sv = a1["stress"][order1, sv_comp]

    # Column height: top of the top particles (a particle spans Y0 +- half its size).
    size0 = a0["initialVolume"][order0] ** (1.0 / dim)
    H = np.max(Y0 + 0.5 * size0)

    sv_ref = -rho * gmag * (H - Y0)
    below = Y0 < H - h
    stress_err = np.sqrt(np.sum((sv[below] - sv_ref[below]) ** 2) / np.sum(sv_ref[below] ** 2))

    u = Y0 - Y1  # downwards positive
    u_ref = rho * gmag / M * (H * Y0 - 0.5 * Y0**2)
    top = Y0 > np.max(Y0) - 1e-9 * H
    settle_num = np.mean(u[top])
    settle_ref = np.mean(u_ref[top])
    settle_err = (settle_num - settle_ref) / settle_ref

    # Static? the top settlement at the time before the last.
    xp, ap = read_vtu(os.path.join(case, ts[-2][1], "particles.vtu"))
    orderp = np.argsort(ap["id"])
    settle_prev = np.mean((Y0 - xp[orderp, up])[top])
    static_change = abs(settle_num - settle_prev) / abs(settle_num)

    ke_ratio = float("nan")
    edat = os.path.join(case, "postProcessing", "energy", "0", "energy.dat")
    if os.path.isfile(edat):
        e = np.loadtxt(edat)
        if e.ndim == 2 and e.shape[0] > 1 and np.max(e[:, 1]) > 0:
            ke_ratio = e[-1, 1] / np.max(e[:, 1])

    # Base reaction (boundaryReaction function object): at rest the floor carries the weight,
    # F = -m g, averaged over the last write interval.
    # The total vertical reaction sums the vertical components over all faces: the monitor
    # charges a node on two walls (a corner) to the first of them, so part of the floor's load
    # (the damping force at those nodes) can show on the side walls.
    reaction = reaction_err = reaction_total = reaction_total_err = float("nan")
    weight = np.sum(a1["mass"]) * gmag
    files = sorted(glob.glob(os.path.join(case, "postProcessing", "reactions", "*", "reactions.dat")))
    if files:
        data = np.loadtxt(files[-1], comments="#", ndmin=2)
        with open(files[-1]) as fh:
            cols = [ln for ln in fh if ln.startswith("# time")][0].split()[1:]
        vertical = "_Fy" if dim == 2 else "_Fz"
        last = data[data[:, 0] > ts[-2][0]]
        reaction = -np.mean(last[:, cols.index(("yMin" if dim == 2 else "zMin") + vertical)])
        reaction_err = (reaction - weight) / weight
        reaction_total = -sum(np.mean(last[:, k]) for k, c in enumerate(cols) if c.endswith(vertical))
        reaction_total_err = (reaction_total - weight) / weight

    return dict(dim=dim, h=h, rho=rho, gmag=gmag, M=M, H=H, n=len(Y0), t_end=ts[-1][1],
                t_prev=ts[-2][1], stress_err=stress_err, settle_num=settle_num,
                settle_ref=settle_ref, settle_err=settle_err, static_change=static_change,
                ke_ratio=ke_ratio, reaction=reaction, weight=weight, reaction_err=reaction_err,
                reaction_total=reaction_total, reaction_total_err=reaction_total_err,
                cost=solver_cost(os.path.join(case, "log.mpmFoam")), Y0=Y0, sv=sv, u=u,
                below=below)


def elastic_column_passes(r, tol=ELASTIC_COLUMN_TOL):
    """Whether the result `r` of elastic_column is within `tol` (keys as ELASTIC_COLUMN_TOL;
    a missing reaction file is not checked)."""
    reaction_ok = not np.isfinite(r["reaction_err"]) or abs(r["reaction_err"]) < tol["reaction"]
    return bool(r["stress_err"] < tol["stress"] and abs(r["settle_err"]) < tol["settle"]
                and r["static_change"] < tol["static"] and reaction_ok)


# ---- axial vibration of an elastic bar ---------------------------------------------------------
# Reference: a bar fixed at x = 0 and free at x = L, started with the first mode's velocity,
# vibrates with period T = 4L/c, c = sqrt(E/rho) (nu = 0). The kinetic energy
# K(t) = K0 cos^2(2 pi t / T) has period T/2: its minima (found in postProcessing/energy,
# refined by a parabola through the three samples around each) are fitted by t_k = t0 + k T/2.

#: Tolerance of the tutorial: relative period error (FLIP and APIC).
AXIAL_PERIOD_TOL = 0.01


def kinetic_minima(t, k):
    """Times of the interior local minima of k(t), refined by a parabola (3 samples)."""
    out = []
    for i in range(1, len(k) - 1):
        if k[i] < k[i - 1] and k[i] <= k[i + 1]:
            t0, t1, t2 = t[i - 1], t[i], t[i + 1]
            k0, k1, k2 = k[i - 1], k[i], k[i + 1]
            # vertex of the parabola through the three points (non-uniform spacing allowed)
            den = (t0 - t1) * (t0 - t2) * (t1 - t2)
            a = (t2 * (k1 - k0) + t1 * (k0 - k2) + t0 * (k2 - k1)) / den
            b = (t2**2 * (k0 - k1) + t1**2 * (k2 - k0) + t0**2 * (k1 - k2)) / den
            out.append(-b / (2 * a) if a > 0 else t1)
    return np.array(out)


def axial_reference(case):
    """dict(E, rho, L, h, c, T_ref) of the bar in `case` (c = sqrt(E/rho), T_ref = 4L/c)."""
    const = os.path.join(case, "constant")
    E = read_yaml_scalar(os.path.join(const, "materials"), "E")
    rho = read_yaml_scalar(os.path.join(const, "materials"), "density")
    nu = read_yaml_scalar(os.path.join(const, "materials"), "nu")
    if nu != 0:
        raise SystemExit("validate: this check assumes nu = 0 (c = sqrt(E/rho))")
    with open(os.path.join(const, "particles")) as f:
        L = float(re.search(r"length\s*:\s*([-+0-9.eE]+)", f.read()).group(1))
    h = read_yaml_scalar(os.path.join(const, "grid"), "cellSize")
    c = np.sqrt(E / rho)
    return dict(E=E, rho=rho, L=L, h=h, c=c, T_ref=4 * L / c)


def axial_vibration(run):
    """Period and energy drift of the bar run in folder `run`, or None without its energy file.

    Returns a dict: the axial_reference entries, finite (the energy is finite), T (measured
    period, NaN with fewer than two kinetic-energy minima), perr (signed relative period
    error), nmin (minima found), drift (|E(end) - E(0)| / E(0)), mean_drift (the same with the
    means of E over the first and the last period: E also oscillates at twice the vibration
    frequency), t_end, cost (solver_cost) and the curves t/T, E/E(0), K/E(0).
    """
    ref = axial_reference(run)
    edat = os.path.join(run, "postProcessing", "energy", "0", "energy.dat")
    if not os.path.isfile(edat):
        return None
    e = np.loadtxt(edat, ndmin=2)
    out = dict(ref, finite=bool(np.all(np.isfinite(e))), cost=solver_cost(os.path.join(run, "log.mpmFoam")))
    if not out["finite"]:
        return out
    t, kin, tot = e[:, 0], e[:, 1], e[:, 4]
    T_ref = ref["T_ref"]
    mins = kinetic_minima(t, kin)
    T = 2 * np.polyfit(np.arange(len(mins)), mins, 1)[0] if len(mins) >= 2 else float("nan")
    first = t <= t[0] + T_ref
    last = t >= t[-1] - T_ref
    out.update(T=T, perr=(T - T_ref) / T_ref, nmin=len(mins), drift=abs(tot[-1] - tot[0]) / tot[0],
               mean_drift=abs(np.mean(tot[last]) - np.mean(tot[first])) / tot[0], t_end=t[-1],
               curves=(t / T_ref, tot / tot[0], kin / tot[0]))
    return out
