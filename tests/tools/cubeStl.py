#!/usr/bin/env python3
"""Write an ascii STL of an axis-aligned cube centred at the origin, outward-facing.

Usage: cubeStl.py <file.stl> <half edge [m]>
"""
import sys

path, a = sys.argv[1], float(sys.argv[2])
with open(path, "w") as f:
    f.write("solid cube\n")
    for axis in range(3):
        for s in (-1, 1):
            o = [(axis + 1) % 3, (axis + 2) % 3]
            q = []
            for u, v in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [0.0] * 3
                p[axis], p[o[0]], p[o[1]] = s * a, u * a, v * a
                q.append(p)
            if s < 0:
                q.reverse()
            for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3])):
                f.write(" facet normal 0 0 0\n  outer loop\n")
                for p in t:
                    f.write("   vertex %g %g %g\n" % tuple(p))
                f.write("  endloop\n endfacet\n")
    f.write("endsolid cube\n")
