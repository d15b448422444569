#!/usr/bin/env bash
# Gravity preload [000 §4.2] (initialStress: gravityPreload): a stress-free Drucker-Prager bed
# is loaded by gravity with local damping until its kinetic energy is 1e-4 of its peak for a whole period; the
# state written at t = 0 must be at rest, denser than the initial density (so the trans-phase
# rule does not gasify it), and carry the vertical stress -rho g (H - y) (relative L2 error
# below 3 % over the points below the top cell layer).
set -euo pipefail
root=${MPMFOAM_DIR:-$(cd "$(dirname "$0")/../.." && pwd)}
py=${MPMFOAM_PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$root/tests/cases/preload2D" "$work/case"
"$root/bin/mpmFoam" -case "$work/case" >"$work/log" 2>&1 || { cat "$work/log"; exit 1; }
grep "Gravity preload" "$work/log"
"$py" - "$work/case/0/particles.vtu" <<'PY'
import sys, numpy as np, vtk
from vtk.util.numpy_support import vtk_to_numpy as arr
r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(sys.argv[1]); r.Update(); o = r.GetOutput()
x = arr(o.GetPoints().GetData()); pd = o.GetPointData()
s = arr(pd.GetArray("stress")); v = arr(pd.GetArray("velocity")); rho = arr(pd.GetArray("density"))
m = arr(pd.GetArray("mass")); v0 = arr(pd.GetArray("initialVolume"))
H = 0.15  # the bed's height; the weight above a point is rho0 g (H - y0), y0 ~ y (settlement << h)
y = x[:, 1]
ref = -1500 * 9.81 * (H - y)
below = y < H - 0.01
err = np.linalg.norm(s[below, 4] - ref[below]) / np.linalg.norm(ref[below])
ok = err < 0.03 and np.abs(v).max() == 0 and (rho >= 1500 * (1 - 1e-12)).all()
print(f"gravityPreload: vertical stress L2 error {100 * err:.2f} % (tolerance 3 %), "
      f"max |v| {np.abs(v).max():g}, density {rho.min():.2f}-{rho.max():.2f} kg/m3: "
      f"{'PASS' if ok else 'FAIL'}")
sys.exit(0 if ok else 1)
PY
