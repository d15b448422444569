#!/usr/bin/env python3
"""Write the two wheel surfaces of the soil-wheel tutorial [004 §5.3] as binary STL.

  constant/geometry/wheel.stl     a grousered wheel: rim cylinder R_RIM with N_GROUSER
                                  straight radial fins (grousers) out to R_TIP, width W
  constant/geometry/cylinder.stl  the control: a smooth cylinder of the mean radius
                                  R_MEAN = (R_RIM + R_TIP)/2, same width

Both are centred at the origin with the wheel axis along y (the body pose is set in
constant/rigidBodies). Each surface is a 2D profile in the x-z plane extruded along y: the
side walls are quads, the two end caps fans from an apex on the axis HUB = 1 cm outside the
face (the profile is star-shaped about the axis), i.e. low conical hubs. The hubs are a
workaround: surfaceToLevelSet gets the sign wrong beyond an end cap that is flat and
perpendicular to its grid rows (the principal x axis, here the wheel axis), see README.md. Triangles are closed (every edge shared by exactly two) and oriented outward;
the script checks both, and the enclosed volume against the exact one.

The paper scales NASA's Mars-2020 wheel (0.525 m diameter, 0.4 m wide, 48 low grousers); our
grousers are fewer and taller (N = 12, 5 cm) so that they are resolved by the h = 4-5 cm MPM
grid of this tutorial (a grouser lower than the point spacing would make the wheel smooth).
Profile edges are at most H_SURF = 8 mm long, as the paper's h_surface (h_LS = min(h,
h_surface) = 8 mm); along the axis the faces are flat and span the width in one triangle.
Usage: makeWheel.py [outputDir]   (default constant/geometry)
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ["MPMFOAM_DIR"], "bin", "tools"))
from stlFile import write_binary_stl  # noqa: E402

R_RIM = 0.20        # m, rim radius (grouser root)
R_TIP = 0.25        # m, grouser tip radius: outer diameter 0.5 m
R_MEAN = 0.5 * (R_RIM + R_TIP)   # m, mean radius r̄ = 0.225 m (also the control cylinder)
W = 0.40            # m, wheel width along y
N_GROUSER = 12      # grousers, evenly spaced
T_GROUSER = 0.024   # m, grouser thickness (tangential; 3 level-set spacings)
HUB = 0.01          # m, the end caps are low cones (hubs) whose apex stands HUB proud
H_SURF = 0.008      # m, largest edge of the surface mesh


def arc(r, a0, a1):
    """Points on the circle of radius r from angle a0 to a1 (excluding a1), edges <= H_SURF."""
    n = max(1, math.ceil(abs(a1 - a0) * r / H_SURF))
    return [(r * math.cos(a), r * math.sin(a)) for a in np.linspace(a0, a1, n, endpoint=False)]


def segment(p, q):
    """Points from p to q (excluding q), edges <= H_SURF."""
    n = max(1, math.ceil(math.dist(p, q) / H_SURF))
    return [tuple(np.add(p, (np.subtract(q, p)) * k / n)) for k in range(n)]


def grouseredProfile():
    """Counter-clockwise profile (u, v) = (x, z) of the rim with N_GROUSER fins of constant
    thickness: each fin has parallel sides at ±T/2 from its radial centre line."""
    pts = []
    da = 2 * math.pi / N_GROUSER
    aRim, aTip = math.asin(0.5 * T_GROUSER / R_RIM), math.asin(0.5 * T_GROUSER / R_TIP)
    for i in range(N_GROUSER):
        a = i * da
        rim0 = (R_RIM * math.cos(a - aRim), R_RIM * math.sin(a - aRim))
        tip0 = (R_TIP * math.cos(a - aTip), R_TIP * math.sin(a - aTip))
        tip1 = (R_TIP * math.cos(a + aTip), R_TIP * math.sin(a + aTip))
        rim1 = (R_RIM * math.cos(a + aRim), R_RIM * math.sin(a + aRim))
        pts += segment(rim0, tip0) + segment(tip0, tip1) + segment(tip1, rim1)
        pts += arc(R_RIM, a + aRim, a + da - aRim)          # rim between two fins
    return np.array(pts)


def grouseredVolume():
    """Exact cross-section area A x W + two hub cones A HUB / 3: rim disc + N fins."""
    aRim, aTip = math.asin(0.5 * T_GROUSER / R_RIM), math.asin(0.5 * T_GROUSER / R_TIP)
    # one fin beyond the rim: trapezoid-like region between the parallel sides, the rim arc
    # and the tip arc = (sector area between the arcs) computed as polygon + circular segments
    fin = (0.5 * R_TIP**2 * (2 * aTip - math.sin(2 * aTip))        # tip circular segment
           + T_GROUSER * (R_TIP * math.cos(aTip) - R_RIM * math.cos(aRim))   # rectangle
           - 0.5 * R_RIM**2 * (2 * aRim - math.sin(2 * aRim)))      # rim segment inside disc
    return (math.pi * R_RIM**2 + N_GROUSER * fin) * (W + 2 * HUB / 3)


def extrude(profile):
    """Closed triangle list of the profile extruded over y in [-W/2, W/2], outward normals.
    A profile point (u, v) goes to (x, y, z) = (u, y, v)."""
    n = len(profile)
    P = lambda p, y: (p[0], y, p[1])  # noqa: E731
    y0, y1 = -0.5 * W, 0.5 * W
    tris = []
    for i in range(n):
        a, b = profile[i], profile[(i + 1) % n]
        tris += [(P(a, y0), P(b, y0), P(b, y1)), (P(a, y0), P(b, y1), P(a, y1))]   # side
        tris += [((0, y0 - HUB, 0), P(b, y0), P(a, y0)),                             # hubs
                 ((0, y1 + HUB, 0), P(a, y1), P(b, y1))]
    T = np.array(tris, dtype=float)
    # The (x, z) profile is counter-clockwise seen with z up and x right, i.e. seen from -y;
    # fix the orientation from the signed volume rather than trusting that reasoning.
    if signedVolume(T) < 0:
        T = T[:, ::-1, :]
    return T


def signedVolume(T):
    return np.einsum("ij,ij->i", T[:, 0], np.cross(T[:, 1], T[:, 2])).sum() / 6.0


def checkClosed(T):
    """Every directed edge appears once and its reverse once: closed and consistently oriented."""
    key = lambda p: tuple(np.round(p, 9))  # noqa: E731
    edges = {}
    for t in T:
        for k in range(3):
            e = (key(t[k]), key(t[(k + 1) % 3]))
            edges[e] = edges.get(e, 0) + 1
    bad = [e for e, c in edges.items() if c != 1 or edges.get((e[1], e[0]), 0) != 1]
    if bad:
        sys.exit(f"makeWheel: surface not closed/oriented ({len(bad)} bad edges)")


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "constant/geometry"
    os.makedirs(out, exist_ok=True)
    surfaces = {
        "wheel": (grouseredProfile(), grouseredVolume()),
        "cylinder": (np.array(arc(R_MEAN, 0, 2 * math.pi)),
                     math.pi * R_MEAN**2 * (W + 2 * HUB / 3)),
    }
    for name, (profile, exact) in surfaces.items():
        T = extrude(profile)
        checkClosed(T)
        V = signedVolume(T)
        write_binary_stl(os.path.join(out, name + ".stl"), T, name)
        print(f"makeWheel: {name}.stl: {len(T)} triangles, volume {V:.6f} m3 "
              f"(exact {exact:.6f}, {100 * (V / exact - 1):+.2f} %)")
    print(f"makeWheel: R_rim = {R_RIM} m, R_tip = {R_TIP} m, mean radius {R_MEAN} m, "
          f"width {W} m, {N_GROUSER} grousers {T_GROUSER} m thick, hubs {HUB} m")


if __name__ == "__main__":   # validate imports the dimensions
    main()
