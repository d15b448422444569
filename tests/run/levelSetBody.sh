#!/usr/bin/env bash
# A level-set rigid body end to end (issue 4, first part): surfaceToLevelSet turns a cube STL
# into constant/levelSets/cube.vti, and mpmFoam drops that body (type levelSet) onto a small
# Drucker-Prager bed: the run ends normally, no point ever ends a step inside the cube
# (contactGap > 0), the sand stops the cube (it ends slower than free fall would make it),
# and rigidBodies.vtp holds its surface. A level set coarser than the grid is warned about.
set -euo pipefail
root=${MPMFOAM_DIR:-$(cd "$(dirname "$0")/../.." && pwd)}
py=${MPMFOAM_PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
c=$work/case
mkdir -p "$c/system" "$c/constant/geometry"
"$py" "$root/tests/tools/cubeStl.py" "$c/constant/geometry/cube.stl" 0.02
cat >"$c/system/surfaceToLevelSetDict" <<'YAML'
surfaces:
  cube: {file: cube.stl, spacing: 0.004, padding: 0.02}
YAML
cat >"$c/system/controlDict" <<'YAML'
application: mpmFoam
endTime: 0.05
deltaT: 4.0e-5
writeControl: adjustableRunTime
writeInterval: 0.025
functions:
  body: {type: rigidBodyState}
  gap: {type: contactGap}
  com: {type: centreOfMass, material: sand}
YAML
printf 'kernel: gimp\ntransfer: {type: flip, ratio: 0.995}\n' >"$c/system/mpmSchemes"
echo 'value: [0, 0, -9.81]' >"$c/constant/g"
cat >"$c/constant/grid" <<'YAML'
dimension: 3
bounds: {min: [0, 0, 0], max: [0.12, 0.12, 0.12]}
cellSize: 0.008
boundary: {zMax: open}
YAML
echo 'sand: {type: druckerPrager, density: 1500, E: 1.0e6, nu: 0.3, frictionAngle: 30, coneFit: compression}' >"$c/constant/materials"
cat >"$c/constant/particles" <<'YAML'
bed:
  material: sand
  region: {type: box, min: [0, 0, 0], max: [0.12, 0.12, 0.048]}
  seeding: {method: regular, perDirection: 2}
  initialStress: geostatic
YAML
cat >"$c/constant/rigidBodies" <<'YAML'
cube:
  shape: {type: levelSet, file: constant/levelSets/cube.vti}
  density: 2500
  position: [0.06, 0.06, 0.07]
  velocity: [0, 0, -1.5]
  coupling: {type: barrier, friction: 0.3}
YAML
(cd "$c" && "$root/bin/surfaceToLevelSet" -case . >log.surfaceToLevelSet 2>&1) || { cat "$c/log.surfaceToLevelSet"; exit 1; }
# From outside the case: the level-set file is found relative to the case directory.
(cd "$work" && "$root/bin/mpmFoam" -case "$c" >"$c/log.mpmFoam" 2>&1) || { tail -20 "$c/log.mpmFoam"; exit 1; }
"$py" - "$c" <<'PY'
import sys, numpy as np, vtk
case = sys.argv[1]
gap = np.loadtxt(case + "/postProcessing/gap/0/gap.dat", comments="#", ndmin=2)
body = np.loadtxt(case + "/postProcessing/body/0/body.dat", comments="#", ndmin=2)
com = np.loadtxt(case + "/postProcessing/com/0/com.dat", comments="#", ndmin=2)
massDrift = abs(com[:, 1] / com[0, 1] - 1).max()
expected = 1500 * 0.12 * 0.12 * 0.048
vz = body[-1, 6]
freeFall = -1.5 - 9.81 * body[-1, 0]
r = vtk.vtkXMLPolyDataReader(); r.SetFileName(case + "/0.05/rigidBodies.vtp"); r.Update()
tris = r.GetOutput().GetNumberOfCells()
ok = (gap[:, 2].min() > 0 and abs(vz) < 0.5 * abs(freeFall) and tris > 0
      and massDrift < 1e-12 and abs(com[0, 1] / expected - 1) < 1e-9)
print(f"levelSetBody: smallest gap {gap[:, 2].min():.3e} m, final vz {vz:.3f} m/s "
      f"(free fall {freeFall:.3f}), {tris} surface triangles, sand mass {com[0, 1]:.6g} kg "
      f"(box {expected:.6g}, drift {massDrift:.1e}): {'PASS' if ok else 'FAIL'}")
sys.exit(0 if ok else 1)
PY

# A level set coarser than the MPM grid gets a warning [004 §5.2].
sed -i 's/spacing: 0.004/spacing: 0.012/' "$c/system/surfaceToLevelSetDict"
rm -rf "$c"/0* "$c"/postProcessing "$c"/*.pvd
"$root/bin/surfaceToLevelSet" -case "$c" >"$c/log.surfaceToLevelSet.coarse" 2>&1
"$root/bin/mpmFoam" -case "$c" -dry-run >"$c/log.dryRun" 2>&1
grep -q "coarser than the MPM cell size" "$c/log.dryRun" ||
    { echo "FAIL: no warning for a level set coarser than the grid"; exit 1; }
echo "levelSetBody: a level set coarser than the MPM grid is warned about"
