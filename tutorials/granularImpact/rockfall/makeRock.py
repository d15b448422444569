#!/usr/bin/env python3
"""Boulder mesh of the rockfall tutorial: constant/geometry/rock.stl, in metres.

The rock of tutorials/levelSet/droppedRock (its makeRock.py, imported by path: the same
lumpy, elongated icosphere, 92 x 59 x 45 mm, 127 cm^3) scaled by SCALE = 7.7, which gives a
boulder of 0.71 x 0.45 x 0.35 m and 0.058 m^3: 153.7 kg at rho = 2650 kg/m^3 (granite).

It also prints what constant/rigidBodies needs to start the boulder just above the bed: the
volume centroid, and the depth of the lowest point below the centroid once the mesh is turned
by the orientation of constant/rigidBodies (a level-set body turns about its centroid).

Usage: makeRock.py [-scale S] [output.stl]
"""
import importlib.util
import os
import sys

import numpy as np

sys.dont_write_bytecode = True  # leave no __pycache__ in the droppedRock tutorial
here = os.path.dirname(os.path.abspath(__file__))
spec = importlib.util.spec_from_file_location(
    "droppedRockMesh", os.path.join(here, "..", "..", "levelSet", "droppedRock", "makeRock.py"))
mesh = importlib.util.module_from_spec(spec)
spec.loader.exec_module(mesh)  # also puts bin/tools on sys.path
from stlFile import write_binary_stl  # noqa: E402

SCALE = 7.7
ORIENTATION = ([0.3, 1, 0], 40.0)  # axis, angle [deg]: as in constant/rigidBodies


def rotation(axis, deg):
    """Rotation matrix about `axis` by `deg` degrees (Rodrigues)."""
    u = np.asarray(axis, float) / np.linalg.norm(axis)
    a = np.radians(deg)
    k = np.array([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]])
    return np.eye(3) + np.sin(a) * k + (1 - np.cos(a)) * k @ k


def volume_centroid(tris):
    """Volume and centroid of a closed, outward-oriented triangle mesh."""
    v6 = np.einsum("ij,ij->i", tris[:, 0], np.cross(tris[:, 1], tris[:, 2]))
    return v6.sum() / 6.0, (v6[:, None] * tris.sum(axis=1)).sum(axis=0) / (4.0 * v6.sum())


if __name__ == "__main__":
    args = sys.argv[1:]
    scale = SCALE
    if args[:1] == ["-scale"]:
        scale, args = float(args[1]), args[2:]
    out = args[0] if args else os.path.join(here, "constant", "geometry", "rock.stl")
    x, f = mesh.rock()
    tris = scale * x[f]
    vol, c = volume_centroid(tris)
    assert vol > 0, "the rock must be outward oriented"
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    write_binary_stl(out, tris, f"rock: rockfall makeRock.py, droppedRock's rock x {scale:g}")
    turned = (scale * x - c) @ rotation(*ORIENTATION).T
    print(f"rock.stl: {len(x)} vertices, {len(f)} triangles, scale {scale:g}, volume "
          f"{vol:.5f} m^3 ({2650 * vol:.1f} kg at 2650 kg/m^3), volume-equivalent diameter "
          f"{(6 * vol / np.pi) ** (1 / 3):.4f} m, extent {np.round(scale * (x.max(0) - x.min(0)), 3)} m")
    print(f"centroid {np.round(c, 5)} m; turned by {ORIENTATION[1]:g} deg about "
          f"{ORIENTATION[0]}: lowest point {-turned[:, 2].min():.4f} m below the centroid, "
          f"highest {turned[:, 2].max():.4f} m above, horizontal extent "
          f"{np.round(turned[:, :2].max(0) - turned[:, :2].min(0), 3)} m")
