#!/usr/bin/python3
"""Share of the points of a Drucker–Prager run that yield (benchmark check, not a test).

    tests/benchmarks/yieldShare.py particles.vtu frictionAngle [--coneFit compression]

Reads the VTU's stress and plasticStrain and prints, at that time, the share of points
  - on the cone: p > 0 and q >= (1 - 1e-6) mu p (they returned this step or sit on the surface),
  - at the apex: sigma = 0 (the stress-free return of a tensile trial, cohesionless Hencky),
  - inside the elastic region,
and the share whose accumulated plastic strain exceeds 1e-6, 1e-4, 1e-3 and 1e-2.
p = -tr(sigma)/3, q = sqrt(J2), mu = 2 sqrt(3) sin(phi)/(3 - sin(phi)) (docs/caseFormat.md).
"""
import argparse
import math

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("vtu")
    ap.add_argument("frictionAngle", type=float, help="degrees")
    ap.add_argument("--coneFit", choices=["compression", "planeStrain"], default="compression")
    a = ap.parse_args()
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(a.vtu)
    r.Update()
    pd = r.GetOutput().GetPointData()
    if pd.GetArray("stress") is None or pd.GetArray("plasticStrain") is None:
        raise SystemExit(f"{a.vtu}: no 'stress' or 'plasticStrain' point array")
    s = vtk_to_numpy(pd.GetArray("stress")).reshape(-1, 3, 3)
    ps = vtk_to_numpy(pd.GetArray("plasticStrain"))
    phi = math.radians(a.frictionAngle)
    if a.coneFit == "compression":
        mu = 2 * math.sqrt(3) * math.sin(phi) / (3 - math.sin(phi))
    else:
        mu = 3 * math.tan(phi) / math.sqrt(9 + 12 * math.tan(phi) ** 2)
    p = -np.trace(s, axis1=1, axis2=2) / 3
    dev = s + p[:, None, None] * np.eye(3)
    q = np.sqrt(0.5 * np.einsum("nij,nij->n", dev, dev))
    apex = np.all(s == 0, axis=(1, 2))
    cone = ~apex & (p > 0) & (q >= (1 - 1e-6) * mu * p)
    n = len(ps)
    pct = lambda m: 100.0 * np.count_nonzero(m) / n
    print(f"{n} points, phi = {a.frictionAngle} deg (mu = {mu:.4f}): on the cone {pct(cone):.1f} %, "
          f"at the apex {pct(apex):.1f} %, elastic {pct(~cone & ~apex):.1f} %")
    print("accumulated plastic strain > " +
          ", ".join(f"{t:g}: {pct(ps > t):.1f} %" for t in (1e-6, 1e-4, 1e-3, 1e-2)) +
          f"; max {ps.max():.3g}")


if __name__ == "__main__":
    main()
