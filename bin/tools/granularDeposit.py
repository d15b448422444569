"""Measures of a granular collapse's deposit (numpy and vtk only), shared by
tutorials/granularFlows/columnCollapse2D and columnCollapse3D:

    import granularDeposit as gd
    for t, d in gd.frames(case): ...          # d = gd.read(path): points and fields
    r = gd.front(radius, h)                   # end of the continuous deposit
    loose, ratio, n = gd.deposit(d, h, dim)   # does the resting deposit carry its weight?

The vertical axis is the last one (y in 2D, z in 3D); the horizontal distance from the column's
axis is x in 2D and √(x² + y²) in 3D.
"""
import os

import numpy as np

import verification

G = 9.81


def read(path):
    """Points "x" (n, 3) and the point fields "stress" (n, 9), "mass", "volume" of a frame."""
    x, f = verification.read_vtu(path)
    return {"x": x, "stress": f["stress"], "mass": f["mass"], "volume": f["volume"]}


def frames(case):
    """Sorted [(time, path of particles.vtu)] of a case's written times."""
    return [(t, os.path.join(case, d, "particles.vtu")) for t, d in verification.time_dirs(case)]


def radius(x, dim):
    """Horizontal distance from the column's axis (x = 0 in 2D, the z axis in 3D)."""
    return x[:, 0] if dim == 2 else np.hypot(x[:, 0], x[:, 1])


def front(r, h):
    """The end of the continuous deposit: the last point before a gap of more than 1.5 cells in
    the sorted horizontal distances (grains thrown ahead of it do not count)."""
    rs = np.sort(r)
    gaps = np.where(np.diff(rs) > 1.5 * h)[0]
    return rs[gaps[0]] if len(gaps) else rs[-1]


def height(d, h, dim):
    """The deposit's highest point; the material's surface lies a quarter cell above the top
    point (2 points per cell and direction)."""
    return d["x"][:, dim - 1].max() + h / 4


def occupied(d, h, dim):
    """The space under the deposit's surface over the points' own volume Σ V_p: the surface is
    the highest point of each column of cells (+ h/4), the floor z = 0. Below 1 where the points
    bunched up without their volumes following (they claim more space than they fill); a real
    deposit is slightly looser than the column, not denser (Balmforth & Kerswell 2005: its area
    grows by about 10 %)."""
    x = d["x"]
    cells = np.floor(x[:, : dim - 1] / h).astype(int)
    _, col = np.unique(cells, axis=0, return_inverse=True)
    top = np.full(col.max() + 1, -np.inf)
    np.maximum.at(top, col.ravel(), x[:, dim - 1])
    return (top + h / 4).sum() * h ** (dim - 1) / d["volume"].sum()


def deposit(d, h, dim):
    """(share of the points more than two cells below the free surface that carry no stress,
    Σσ_v / Σ ρ g depth over those points, their number). The free surface is the highest point
    of each column of cells (+ h/4); ρ the deposit's bulk density Σm/ΣV."""
    x = d["x"]
    cells = np.floor(x[:, : dim - 1] / h).astype(int)
    _, col = np.unique(cells, axis=0, return_inverse=True)
    col = col.ravel()
    z = x[:, dim - 1]
    top = np.full(col.max() + 1, -np.inf)
    np.maximum.at(top, col, z)
    depth = top[col] - z + h / 4
    deep = depth > 2 * h
    loose = np.abs(d["stress"]).max(axis=1) == 0
    rho = d["mass"].sum() / d["volume"].sum()
    sv = -d["stress"][:, 4 if dim == 2 else 8]
    ratio = sv[deep].sum() / (rho * G * depth[deep]).sum()
    return loose[deep].mean(), ratio, int(deep.sum())


def virial(d, dim):
    """Σ σ_v V_p / Σ m_p g z_p over all points: 1 for any body at rest on a level floor whose
    other faces are traction-free or frictionless symmetry planes (∫ σ_zz dV = −∫ ρ g z dV, the
    virial of the momentum balance; the floor's traction acts at z = 0 and the symmetry planes
    carry no shear)."""
    z = d["x"][:, dim - 1]
    sv = d["stress"][:, 4 if dim == 2 else 8]
    return -(sv * d["volume"]).sum() / (d["mass"] * G * z).sum()


def restSpeed(path):
    """The speed [m/s] that 99 % of the points are below in a frame (a few rattling points of
    a deposit at rest do not count)."""
    _, f = verification.read_vtu(path)
    return float(np.percentile(np.linalg.norm(f["velocity"], axis=1), 99))


def snapshot(frames, out, dim, title, cut=None):
    """A picture of the material: the points of each (label, path) in `frames` coloured by the
    pressure p = −tr σ/3 [kPa] (grey: stress-free), one panel each; in 3D the points within
    `cut` of the plane y = x (a section through the axis), plotted against the distance from
    the axis."""
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(len(frames), 1, figsize=(10, 1.0 + 2.2 * len(frames)), squeeze=False)
    for ax, (label, path) in zip(axes[:, 0], frames):
        d = read(path)
        x = d["x"]
        p = -(d["stress"][:, 0] + d["stress"][:, 4] + d["stress"][:, 8]) / 3e3
        if dim == 3:
            keep = np.abs(x[:, 0] - x[:, 1]) < cut
            x, p = np.c_[radius(x[keep], 3), x[keep, 2]], p[keep]
        free = p == 0
        size = float(np.clip(2e4 / len(p), 0.5, 6))
        ax.scatter(x[free, 0], x[free, 1], s=size, c="0.75", lw=0)
        sc = ax.scatter(x[~free, 0], x[~free, 1], s=size, c=p[~free], cmap="viridis", lw=0,
                        vmax=np.percentile(p[~free], 99) if (~free).any() else None)
        ax.set_aspect("equal")
        ax.set_title(label, fontsize=9)
        fig.colorbar(sc, ax=ax, label="p [kPa]", fraction=0.02)
    axes[-1, 0].set_xlabel("x [m]" if dim == 2 else "distance from the axis [m]")
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)
