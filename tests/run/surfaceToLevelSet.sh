#!/usr/bin/env bash
# surfaceToLevelSet end to end: a 0.1 m cube written as an ascii STL becomes
# constant/levelSets/cube.vti; VTK's reader loads it, phi equals the exact signed distance
# inside and outside, and the field data carries the cube's volume. A misspelt key is an
# error with file, line and key, exit code 1.
set -euo pipefail
root=${MPMFOAM_DIR:-$(cd "$(dirname "$0")/../.." && pwd)}
py=${MPMFOAM_PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
c=$work/case
mkdir -p "$c/system" "$c/constant/geometry"
"$py" "$root/tests/tools/cubeStl.py" "$c/constant/geometry/cube.stl" 0.05
cat >"$c/system/surfaceToLevelSetDict" <<'YAML'
surfaces:
  cube: {file: cube.stl, spacing: 0.005, padding: 0.02}
YAML
"$root/bin/surfaceToLevelSet" -case "$c" >"$work/log" 2>&1 || { cat "$work/log"; exit 1; }
"$py" - "$c/constant/levelSets/cube.vti" <<'PY'
import sys, numpy as np, vtk
from vtk.util.numpy_support import vtk_to_numpy as arr
r = vtk.vtkXMLImageDataReader(); r.SetFileName(sys.argv[1]); r.Update(); o = r.GetOutput()
phi = arr(o.GetPointData().GetArray("phi")).astype(float)
n = o.GetNumberOfPoints()
centre = o.FindPoint(0.0, 0.0, 0.0)
corner = o.FindPoint(*o.GetPoint(0))
def box(x):  # exact signed distance to the cube of half-edge 0.05
    q = np.abs(np.array(x)) - 0.05
    return np.linalg.norm(np.maximum(q, 0.0)) + min(q.max(), 0.0)
exact, inside = box(o.GetPoint(corner)), box(o.GetPoint(centre))
vol = o.GetFieldData().GetArray("volume").GetValue(0)
ok = abs(phi[centre] - inside) < 1e-6 and abs(phi[corner] - exact) < 1e-6 and abs(vol - 1e-3) < 1e-9
print(f"surfaceToLevelSet: {n} points, phi(centre) {phi[centre]:.6f} (exact {inside:.6f}), phi(corner) "
      f"{phi[corner]:.6f} (exact {exact:.6f}), volume {vol:.3e}: {'PASS' if ok else 'FAIL'}")
sys.exit(0 if ok else 1)
PY
sed -i 's/spacing:/spacng:/' "$c/system/surfaceToLevelSetDict"
rc=0
"$root/bin/surfaceToLevelSet" -case "$c" >"$work/log" 2>"$work/err" || rc=$?
grep -q "system/surfaceToLevelSetDict:2" "$work/err" && grep -q "spacng" "$work/err" && [ "$rc" -eq 1 ] ||
    { echo "FAIL: misspelt key not reported (exit $rc)"; cat "$work/err"; exit 1; }
echo "surfaceToLevelSet: misspelt key reported with file, line and key"
