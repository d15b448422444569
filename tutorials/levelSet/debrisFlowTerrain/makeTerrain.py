#!/usr/bin/env python3
"""Terrain and source material of the debris-flow tutorial [004 §5.4], numpy only.

Writes
  constant/geometry/terrain.stl   a closed, outward-oriented solid in world coordinates: the
                                  terrain surface z(x, y) (a height field) extruded down to a
                                  flat base, with four vertical side walls;
  constant/particles              the source: a slab of material lying on the upper slope,
                                  written as stair-stepped boxes whose bottoms follow the
                                  terrain (a box region cannot follow a slope).

The valley (all lengths in m): a U-shaped channel whose bed descends along x at 32 deg and
bends smoothly (over x ~ 13..23 m) into a flat, wider runout zone; the channel axis shifts
sideways by 4 m through the bend (a dog-leg), and the bed carries a small deterministic
roughness. Small field scale: ~10 m of drop, 48 m x 24 m footprint.

Usage: makeTerrain.py
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ["MPMFOAM_DIR"], "bin", "tools"))
from stlFile import write_binary_stl  # noqa: E402

H_SURFACE = 0.5          # surface triangle size h_surface [m]

# Footprint of the terrain solid; the MPM grid is x in [0, 48], y in [-12, 12], z in [0, 18]:
# the solid reaches 0.5 m beyond it in x and y and its base lies 0.5 m below it.
X0, X1, Y0, Y1, Z_BASE = -0.5, 48.5, -12.5, 12.5, -0.5

S1, S2 = np.tan(np.radians(32.0)), 0.0  # bed slope of the channel and of the runout zone
XT, WT = 18.0, 3.0       # centre and half-width (m) of the slope break
Z0 = 12.0                # bed height at x = 0 (m)


def logcosh(u):
    u = np.abs(u)
    return u + np.log1p(np.exp(-2.0 * u)) - np.log(2.0)


def blend(x):
    """1 on the upper slope, 0 in the runout zone, a tanh step at XT."""
    return 0.5 * (1.0 - np.tanh((x - XT) / WT))


def bed(x):
    """Height of the channel bed along the axis: slope S1 blended into S2 (closed form)."""
    integral = 0.5 * (x - WT * (logcosh((x - XT) / WT) - logcosh(-XT / WT)))
    return Z0 - S2 * x - (S1 - S2) * integral


def axis(x):
    """y of the channel axis: a smooth sideways shift of 4 m through the slope break."""
    return 2.0 * np.tanh((x - XT) / 5.0)


def height(x, y):
    """Terrain height z(x, y): bed + banks + roughness."""
    b = 4.0 * blend(x) + 9.0 * (1.0 - blend(x))     # half-width of the flat floor
    s = 0.8 * blend(x) + 0.25 * (1.0 - blend(x))    # bank slope (39 deg in the channel, 14 in the fan)
    d = np.abs(y - axis(x)) - b
    bank = s * 1.0 * np.logaddexp(0.0, d / 1.0)     # softplus: rounded toe, width ~1 m
    rough = 0.10 * np.sin(2 * np.pi * x / 7.3) * np.cos(2 * np.pi * y / 5.1) \
        + 0.06 * np.sin(2 * np.pi * (x + y) / 3.7)
    return bed(x) + bank + rough


def terrain_triangles(h):
    """Closed triangulated solid: top height field, four side walls, flat base."""
    nx = int(round((X1 - X0) / h))
    ny = int(round((Y1 - Y0) / h))
    xs = np.linspace(X0, X1, nx + 1)
    ys = np.linspace(Y0, Y1, ny + 1)
    X, Y = np.meshgrid(xs, ys, indexing="ij")
    top = np.stack([X, Y, height(X, Y)], axis=-1)          # (nx+1, ny+1, 3)
    tris = []
    # Top: each quad split in two, counter-clockwise seen from above (normal +z, outward).
    a, b, c, d = top[:-1, :-1], top[1:, :-1], top[1:, 1:], top[:-1, 1:]
    tris += [np.stack([a, b, c], -2).reshape(-1, 3, 3), np.stack([a, c, d], -2).reshape(-1, 3, 3)]

    def wall(edge, outward_ccw):
        """Vertical wall under a boundary polyline of the top (edge: (n, 3))."""
        lo = edge.copy()
        lo[:, 2] = Z_BASE
        p, q, r, s = edge[:-1], edge[1:], lo[1:], lo[:-1]
        if outward_ccw:
            return [np.stack([p, s, r], 1), np.stack([p, r, q], 1)]
        return [np.stack([p, q, r], 1), np.stack([p, r, s], 1)]

    # Edges walked with increasing index; the orientation flag makes every normal point out.
    tris += wall(top[:, 0], True)     # y = Y0, normal -y
    tris += wall(top[:, -1], False)   # y = Y1, normal +y
    tris += wall(top[0, :], False)    # x = X0, normal -x
    tris += wall(top[-1, :], True)    # x = X1, normal +x
    # Base: the same grid at Z_BASE, normal -z (so the walls' bottom edges are shared).
    base = top.copy()
    base[..., 2] = Z_BASE
    a, b, c, d = base[:-1, :-1], base[1:, :-1], base[1:, 1:], base[:-1, 1:]
    tris += [np.stack([a, c, b], -2).reshape(-1, 3, 3), np.stack([a, d, c], -2).reshape(-1, 3, 3)]
    return np.concatenate(tris)


def signed_volume(tris):
    return np.einsum("ij,ij->i", tris[:, 0], np.cross(tris[:, 1], tris[:, 2])).sum() / 6.0


# Source slab [004 §5.4, Fig. 15: "source materials" on the upper slope]: 7 m along x on the
# 32 deg bed, 6 m wide (inside the 8 m floor), 2.5 m deep, as boxes 0.5 m long whose bottom
# is 0.1 m above the highest terrain point under the box.
SRC_X, SRC_W, SRC_T, STEP, CLEAR = (2.0, 9.0), 6.0, 2.5, 0.5, 0.1


def source_boxes():
    boxes = []
    for x0 in np.arange(SRC_X[0], SRC_X[1] - 1e-9, STEP):
        yc = axis(x0 + 0.5 * STEP)
        xs = np.linspace(x0, x0 + STEP, 21)
        ys = np.linspace(yc - SRC_W / 2, yc + SRC_W / 2, 61)
        zb = height(*np.meshgrid(xs, ys, indexing="ij")).max() + CLEAR
        boxes.append(((x0, yc - SRC_W / 2, zb), (x0 + STEP, yc + SRC_W / 2, zb + SRC_T)))
    return boxes


if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    tris = terrain_triangles(H_SURFACE)
    os.makedirs(os.path.join(here, "constant", "geometry"), exist_ok=True)
    write_binary_stl(os.path.join(here, "constant", "geometry", "terrain.stl"), tris,
                     "terrain: makeTerrain.py, debris-flow tutorial [004 5.4]")
    vol = signed_volume(tris)
    assert vol > 0, "terrain solid must be outward oriented"
    print(f"terrain.stl: {len(tris)} triangles, h_surface = {H_SURFACE} m, volume {vol:.1f} m^3, "
          f"bed from z = {bed(0.0):.2f} m (x = 0) to {bed(48.0):.2f} m (x = 48)")
    with open(os.path.join(here, "constant", "particles"), "w") as f:
        f.write("# Source slab on the upper slope, written by makeTerrain.py (stair-stepped boxes\n"
                "# whose bottoms follow the terrain) [004 §5.4]. Lengths in m.\n")
        for i, (lo, hi) in enumerate(source_boxes()):
            f.write(f"source{i:02d}:\n  material: debris\n"
                    f"  region: {{type: box, min: [{lo[0]:.4f}, {lo[1]:.4f}, {lo[2]:.4f}], "
                    f"max: [{hi[0]:.4f}, {hi[1]:.4f}, {hi[2]:.4f}]}}\n"
                    f"  seeding: {{method: regular, perDirection: 2}}\n")
    print(f"constant/particles: {len(source_boxes())} boxes, source volume "
          f"{(SRC_X[1] - SRC_X[0]) * SRC_W * SRC_T:.1f} m^3")
