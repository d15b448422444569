#!/usr/bin/env python3
"""Rock mesh of the dropped-rock tutorial, numpy only: constant/geometry/rock.stl.

An icosphere (icosahedron subdivided 3 times: 642 vertices, 1280 triangles) whose radius is
perturbed by a fixed sum of smooth waves (deterministic: no random numbers), then stretched
to semi-axes 45 x 30 x 22 mm. The surface stays star-shaped about the centre, so it is
closed and outward oriented like the icosahedron it comes from; the principal moments of
inertia all differ (an elongated, flattened, lumpy pebble).

Usage: makeRock.py [output.stl]
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ["MPMFOAM_DIR"], "bin", "tools"))
from stlFile import write_binary_stl  # noqa: E402

SEMI_AXES = np.array([0.045, 0.030, 0.022])  # m
LEVELS = 3

# Radial perturbation r(u) = 1 + sum_k a_k sin(k_k . u + phi_k), |r - 1| <= 0.2
WAVES = [  # amplitude, wave vector (rad per unit radius), phase
    (0.08, (2.1, 0.7, -1.3), 0.4),
    (0.06, (-0.9, 2.6, 1.1), 1.9),
    (0.04, (1.7, -1.8, 3.2), 2.7),
    (0.02, (4.3, 2.2, -2.9), 0.8),
]


def icosphere(levels):
    t = (1.0 + 5.0 ** 0.5) / 2.0
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
         (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
         (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    verts = [np.array(p, float) / np.linalg.norm(p) for p in v]
    for _ in range(levels):
        mid, nf = {}, []

        def midpoint(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                m = verts[a] + verts[b]
                verts.append(m / np.linalg.norm(m))
                mid[key] = len(verts) - 1
            return mid[key]
        for a, b, c in f:
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            nf += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        f = nf
    return np.array(verts), np.array(f)


def rock():
    u, f = icosphere(LEVELS)
    r = 1.0 + sum(a * np.sin(u @ np.array(k) + p) for a, k, p in WAVES)
    return (u * r[:, None]) * SEMI_AXES, f


if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "constant", "geometry", "rock.stl")
    x, f = rock()
    tris = x[f]
    vol = np.einsum("ij,ij->i", tris[:, 0], np.cross(tris[:, 1], tris[:, 2])).sum() / 6.0
    assert vol > 0, "the rock must be outward oriented"
    os.makedirs(os.path.dirname(out), exist_ok=True)
    write_binary_stl(out, tris, "rock: makeRock.py, dropped-rock tutorial")
    edge = np.linalg.norm(tris - np.roll(tris, 1, axis=1), axis=2).mean()
    print(f"rock.stl: {len(x)} vertices, {len(f)} triangles, mean edge {1000 * edge:.2f} mm, "
          f"volume {1e6 * vol:.2f} cm^3, extent {np.round(1000 * (x.max(0) - x.min(0)), 1)} mm")
