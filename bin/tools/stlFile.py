"""Binary STL writing for the tutorials' geometry scripts (numpy only).

    import os, sys
    sys.path.insert(0, os.path.join(os.environ["MPMFOAM_DIR"], "bin", "tools"))
    from stlFile import write_binary_stl
    write_binary_stl("constant/geometry/body.stl", triangles, "body: makeBody.py")

`triangles` is an (n, 3, 3) array of corner coordinates [m], wound counter-clockwise seen from
outside (the facet normal is computed from that order).
"""
import numpy as np


def write_binary_stl(path, triangles, header=""):
    """Write `triangles` as a little-endian binary STL with an 80-byte `header`."""
    tris = np.asarray(triangles, dtype=float)
    n = np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0])
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    rec = np.zeros(len(tris), dtype=[("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")])
    rec["n"], rec["v"] = n, tris
    with open(path, "wb") as f:
        f.write(header.encode()[:80].ljust(80, b" "))
        f.write(np.uint32(len(tris)).tobytes())
        f.write(rec.tobytes())
