#!/usr/bin/env python3
"""Write the column meshes of flowPastColumns [004 §5.2] as binary STL (numpy only).

    makeColumns.py <h_surface [m]>

constant/geometry/pillar.stl  a circular pillar, radius 0.025 m
constant/geometry/star.stl    a 5-pointed star prism, tips at 0.03 m, notches at 0.015 m from
                              the axis, one tip pointing upstream (-x), into the flow
Both are prisms along z from z = -0.02 m (below the flume's base, so that the flow meets no
bottom edge) to z = 0.2 m (above the flow); their centroid is (0, 0, 0.09) m. The case puts
three copies in a row with `position`.

The surface is discretised with spacing h_surface: the sides are a structured grid of quads of
about h_surface (two triangles each), the flat caps rings about h_surface apart. Prints, per
mesh, the triangle count and the mean edge length (diagonals included, so about 1.1 h_surface).
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ["MPMFOAM_DIR"], "bin", "tools"))
from stlFile import write_binary_stl  # noqa: E402

Z0, Z1 = -0.02, 0.2   # m, bottom and top of the prisms


def outline_pillar(h, radius=0.025):
    n = max(8, int(round(2 * np.pi * radius / h)))
    a = 2 * np.pi * np.arange(n) / n
    return np.c_[radius * np.cos(a), radius * np.sin(a)]


def outline_star(h, points=5, r_tip=0.03, r_notch=0.015):
    a = np.pi + np.pi * np.arange(2 * points) / points   # first tip at angle pi: towards -x
    r = np.where(np.arange(2 * points) % 2 == 0, r_tip, r_notch)
    corners = np.c_[r * np.cos(a), r * np.sin(a)]
    out = []
    for i in range(2 * points):                          # split each side into pieces of ~h
        p, q = corners[i], corners[(i + 1) % (2 * points)]
        k = max(1, int(round(np.linalg.norm(q - p) / h)))
        out += [p + (q - p) * j / k for j in range(k)]
    return np.array(out)


def prism(outline, h):
    """Triangles (T, 3, 3) of the closed prism over a counter-clockwise polygon that is
    star-shaped about the origin; outward normals by the right-hand rule."""
    n = len(outline)
    nz = max(1, int(round((Z1 - Z0) / h)))
    z = np.linspace(Z0, Z1, nz + 1)
    tris = []
    for i in range(n):                                   # sides
        p, q = outline[i], outline[(i + 1) % n]
        for k in range(nz):
            a, b = np.r_[p, z[k]], np.r_[q, z[k]]
            c, d = np.r_[q, z[k + 1]], np.r_[p, z[k + 1]]
            tris += [(a, b, c), (a, c, d)]
    rings = max(1, int(round(np.abs(outline).max() / h)))
    for zc, up in ((Z1, True), (Z0, False)):             # caps: rings s = j/rings of the outline
        for i in range(n):
            p, q = outline[i], outline[(i + 1) % n]
            for j in range(rings):
                s0, s1 = j / rings, (j + 1) / rings
                a, b = np.r_[s0 * p, zc], np.r_[s0 * q, zc]
                c, d = np.r_[s1 * q, zc], np.r_[s1 * p, zc]
                quad = [(a, d, c)] if j == 0 else [(a, d, c), (a, c, b)]
                tris += quad if up else [(t[0], t[2], t[1]) for t in quad]
    return np.array(tris)


def mean_edge(tris):
    e = np.round(np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]]), 9)
    e = np.sort(e.view([("x", float), ("y", float), ("z", float)]).reshape(-1, 2), axis=1)
    e = np.unique(e.view(float).reshape(-1, 6), axis=0)       # each shared edge once
    return np.linalg.norm(e[:, :3] - e[:, 3:], axis=1).mean()


h = float(sys.argv[1])
os.makedirs("constant/geometry", exist_ok=True)
for name, outline in (("pillar", outline_pillar(h)), ("star", outline_star(h))):
    tris = prism(outline, h)
    write_binary_stl(f"constant/geometry/{name}.stl", tris, "flowPastColumns column")
    print(f"{name}: {len(tris)} triangles, h_surface {h:g} m, mean edge length "
          f"{mean_edge(tris):.4g} m")
