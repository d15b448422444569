#!/usr/bin/python3
"""Case-dependent inputs of the phase model of roofline.py, measured on a finished run.

    tests/benchmarks/phaseStats.py CASE_DIR [--time T]

CASE_DIR is a run of a benchmark case (its constant/grid, constant/materials and the
particles.vtu of the first and of the last (or the given) time directory). Prints, averaged
over the first and the last state:
  activeNodes   grid nodes the solver visits per particle in P2G (clear), grid update and
                G2P: the 4^dim-node blocks around every block holding a particle (its 3^dim
                neighbourhood of blocks, BlockSort::activeNodeBlocks), clipped to the grid;
  massNodes     nodes with mass per particle (the union of the quadratic B-spline stencils);
  sweeps        Jacobi sweeps of symmetricEigen3Batch per batch of 8 particles (the batch
                runs until its slowest lane converges), replayed in numpy on the stored
                elastic left Cauchy-Green tensors of the last state (the next step's trial
                tensors differ by one increment f b f^T);
  plasticShare  share of the points on the yield cone at the last state (druckerPrager only):
                the lanes that take the plastic branch of the return map.
The last line is machine-readable: STATS case=<name> activeNodes=.. massNodes=.. sweeps=..
plasticShare=..
"""
import argparse
import math
import os
import sys

import numpy as np
import vtk
import yaml
from vtk.util.numpy_support import vtk_to_numpy

PAD, BLOCK = 3, 4  # src/grid/Grid.hpp


def read_vtu(path):
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    out = r.GetOutput()
    if out.GetNumberOfPoints() == 0:
        sys.exit(f"phaseStats: {path}: no particles")
    pd = out.GetPointData()
    arrays = {pd.GetArrayName(k): vtk_to_numpy(pd.GetArray(k)) for k in range(pd.GetNumberOfArrays())}
    return vtk_to_numpy(out.GetPoints().GetData()), arrays


def grid_of(case):
    g = yaml.safe_load(open(os.path.join(case, "constant", "grid")))
    dim = int(g["dimension"])
    lo = np.array(g["bounds"]["min"], float)
    hi = np.array(g["bounds"]["max"], float)
    h = float(g["cellSize"])
    n = np.rint((hi - lo) / h).astype(int) + 1 + 2 * PAD
    return dim, lo - PAD * h, h, n


def node_counts(x, dim, origin, h, n):
    """(active nodes, nodes with mass) per particle for positions x."""
    xh = (x[:, :dim] - origin) / h
    nb = (n + BLOCK - 1) // BLOCK
    blocks = np.unique((xh.astype(int) // BLOCK), axis=0)
    active = set()
    for off in np.ndindex(*(3,) * dim):
        c = blocks + np.array(off) - 1
        ok = np.all((c >= 0) & (c < nb), axis=1)
        active.update(map(tuple, c[ok]))
    active = np.array(sorted(active))
    lo = active * BLOCK
    hi = np.minimum(lo + BLOCK, n)
    activeNodes = np.prod(hi - lo, axis=1).sum()
    base = np.floor(xh - 0.5).astype(np.int64)  # quadratic B-spline stencil: base .. base + 2
    stride = np.cumprod(np.concatenate(([1], n[:-1])))
    nodes = []
    for off in np.ndindex(*(3,) * dim):
        nodes.append(((base + np.array(off)) * stride).sum(axis=1))
    massNodes = len(np.unique(np.concatenate(nodes)))
    return activeNodes / len(x), massNodes / len(x)


def jacobi_sweeps(be, lanes=8):
    """Sweeps symmetricEigen3Batch takes per batch (src/core/SymmetricEigen.hpp, replayed)."""
    n = len(be)
    pad = (-n) % lanes
    if pad:
        be = np.concatenate([be, np.repeat(be[-1:], pad, axis=0)])
    a = np.stack([be[:, 0, 0], be[:, 1, 1], be[:, 2, 2], be[:, 0, 1], be[:, 0, 2], be[:, 1, 2]])
    a = a.reshape(6, -1, lanes)
    tol = 1e-30 + 1e-16 * np.abs(a).sum(axis=0)
    sweeps = np.zeros(a.shape[1], int)
    live = np.ones(a.shape[1], bool)
    for _ in range(12):
        done = np.all(np.abs(a[3]) + np.abs(a[4]) + np.abs(a[5]) <= tol, axis=1)
        live &= ~done
        if not live.any():
            break
        sweeps += live
        for P, R, PR, KP, KR in ((0, 1, 3, 4, 5), (0, 2, 4, 3, 5), (1, 2, 5, 3, 4)):
            apr = a[PR].copy()
            d = a[R] - a[P]
            sd = np.where(d >= 0, 1.0, -1.0)
            t = sd * 2.0 * apr / (np.abs(d) + np.sqrt(d * d + 4.0 * apr * apr) + 1e-300)
            c = 1.0 / np.sqrt(t * t + 1.0)
            s = t * c
            a[P] -= t * apr
            a[R] += t * apr
            a[PR] = 0.0
            akp, akr = a[KP].copy(), a[KR].copy()
            a[KP] = c * akp - s * akr
            a[KR] = s * akp + c * akr
    return sweeps.mean()


def cone_share(case, stress):
    mats = yaml.safe_load(open(os.path.join(case, "constant", "materials")))
    m = next(iter(mats.values()))
    if m.get("type") != "druckerPrager":
        return 0.0
    phi = math.radians(float(m["frictionAngle"]))
    mu = 2 * math.sqrt(3) * math.sin(phi) / (3 - math.sin(phi))
    s = stress.reshape(-1, 3, 3)
    p = -np.trace(s, axis1=1, axis2=2) / 3
    dev = s + p[:, None, None] * np.eye(3)
    q = np.sqrt(0.5 * np.einsum("nij,nij->n", dev, dev))
    apex = np.all(s == 0, axis=(1, 2))
    return float(np.mean(~apex & (p > 0) & (q >= (1 - 1e-6) * mu * p)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("case")
    ap.add_argument("--time", help="time directory of the last state (default: the latest)")
    a = ap.parse_args()
    times = sorted((d for d in os.listdir(a.case)
                    if os.path.isfile(os.path.join(a.case, d, "particles.vtu"))), key=float)
    if len(times) < 1:
        sys.exit(f"phaseStats: no time directory with particles.vtu in {a.case}")
    last = a.time or times[-1]
    dim, origin, h, n = grid_of(a.case)
    x0, _ = read_vtu(os.path.join(a.case, times[0], "particles.vtu"))
    x1, f1 = read_vtu(os.path.join(a.case, last, "particles.vtu"))
    c0, c1 = node_counts(x0, dim, origin, h, n), node_counts(x1, dim, origin, h, n)
    active, mass = 0.5 * (c0[0] + c1[0]), 0.5 * (c0[1] + c1[1])
    sweeps = jacobi_sweeps(f1["elasticLeftCauchyGreen"].reshape(-1, 3, 3))
    share = cone_share(a.case, f1["stress"])
    name = os.path.basename(os.path.normpath(a.case))
    print(f"{name}: {len(x1)} particles, times {times[0]} and {last}")
    print(f"  active nodes per particle {active:.4f} (first {c0[0]:.4f}, last {c1[0]:.4f})")
    print(f"  nodes with mass per particle {mass:.4f} (first {c0[1]:.4f}, last {c1[1]:.4f})")
    print(f"  Jacobi sweeps per batch of 8 {sweeps:.3f}; on the yield cone {100 * share:.1f} %")
    print(f"STATS case={name} activeNodes={active:.4f} massNodes={mass:.4f} sweeps={sweeps:.3f} "
          f"plasticShare={share:.3f}")


if __name__ == "__main__":
    main()
