#!/usr/bin/env bash
# surfaceToLevelSet end to end: a 0.1 m cube written as an ascii STL becomes
# constant/levelSets/cube.vti; VTK's reader loads it, phi equals the exact signed distance
# inside and outside, and the field data carries the cube's volume. A misspelt key is an
# error with file, line and key, exit code 1. The case needs system/surfaceToLevelSetDict (not
# yet a controlDict, as in the user guide's boulder): a missing folder or dictionary is an
# error naming it.
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
# Refused with the missing thing named: no such folder; a folder without the dictionary.
rc=0
"$root/bin/surfaceToLevelSet" -case "$work/nowhere" >"$work/log" 2>"$work/err" || rc=$?
[ "$rc" -eq 1 ] && grep -q "nowhere: the case directory does not exist" "$work/err" ||
    { echo "FAIL: a missing case folder not reported (exit $rc)"; cat "$work/err"; exit 1; }
rc=0
"$root/bin/surfaceToLevelSet" -case "$c/constant" >"$work/log" 2>"$work/err" || rc=$?
[ "$rc" -eq 1 ] && grep -q "constant: no system/surfaceToLevelSetDict" "$work/err" &&
    [ ! -e "$c/constant/constant" ] ||
    { echo "FAIL: a folder without system/surfaceToLevelSetDict not reported (exit $rc)"; cat "$work/err"; exit 1; }
echo "surfaceToLevelSet: a missing folder or system/surfaceToLevelSetDict is named"

sed -i 's/spacing:/spacng:/' "$c/system/surfaceToLevelSetDict"
rc=0
"$root/bin/surfaceToLevelSet" -case "$c" >"$work/log" 2>"$work/err" || rc=$?
grep -q "system/surfaceToLevelSetDict:2" "$work/err" && grep -q "spacng" "$work/err" && [ "$rc" -eq 1 ] ||
    { echo "FAIL: misspelt key not reported (exit $rc)"; cat "$work/err"; exit 1; }
echo "surfaceToLevelSet: misspelt key reported with file, line and key"

# Inconsistent winding: two facets of the cube turned inward. The sign (winding number) does not
# mind; the utility warns and reorients them, so the volume and moments stay those of the cube.
sed -i 's/spacng:/spacing:/' "$c/system/surfaceToLevelSetDict"
"$py" - "$c/constant/geometry/cube.stl" <<'PY'
import sys
lines = open(sys.argv[1]).read().split("\n")
vertex = [i for i, l in enumerate(lines) if l.strip().startswith("vertex")]
for first in (0, 9):  # facets 1 and 4: swap their second and third vertices
    a, b = vertex[first + 1], vertex[first + 2]
    lines[a], lines[b] = lines[b], lines[a]
open(sys.argv[1], "w").write("\n".join(lines))
PY
"$root/bin/surfaceToLevelSet" -case "$c" >"$work/log" 2>&1 || { cat "$work/log"; exit 1; }
grep -q "inconsistent orientation" "$work/log" ||
    { echo "FAIL: no warning for inconsistently wound triangles"; cat "$work/log"; exit 1; }
"$py" - "$c/constant/levelSets/cube.vti" <<'PY'
import sys, vtk
r = vtk.vtkXMLImageDataReader(); r.SetFileName(sys.argv[1]); r.Update()
f = r.GetOutput().GetFieldData()
vol = f.GetArray("volume").GetValue(0)
moments = [f.GetArray("principalMoments").GetValue(i) for i in range(3)]
exact = 1e-3 * 0.1 ** 2 / 6  # unit-density cube of edge 0.1: V a² / 6
ok = abs(vol / 1e-3 - 1) < 1e-6 and all(abs(m / exact - 1) < 1e-6 for m in moments)
print(f"surfaceToLevelSet: inconsistent winding warned; volume {vol:.6e}, moments {moments[0]:.4e} "
      f"(exact {exact:.4e}): {'PASS' if ok else 'FAIL'}")
sys.exit(0 if ok else 1)
PY
