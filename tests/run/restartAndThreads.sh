#!/usr/bin/env bash
# Determinism (docs/architecture.md, "Determinism"): for a 2D FLIP/GIMP case and a 3D
# APIC/Hencky case,
#  1. OMP_NUM_THREADS=1 and 2 give bit-identical particles.vtu at every write and identical
#     function-object output;
#  2. a run 0 → T and a run 0 → T/2 resumed to T (startFrom latestTime) give a bit-identical
#     (bodyContact2D, sdemBodies2D: with body–body contact history in uniform/bodyContacts at T/2;
#     viscoelastic2D: with the stored elastic stress σᵉ of flowing points at T/2;
#     slipWalls2D: with the USF wall contact of the last grid update in uniform/wallContact;
#     sdemBlock2D: with the sdem coupling's tangential springs δ_t (contactSlip) at T/2;
#     splitting2D: with points split before T/2 and more split after it)
#     final particles.vtu;
#  3. ParaView's readers (VTK's XML readers) load particles.pvd and every time directory.
set -euo pipefail
. "$(dirname "$0")/../tools/scriptTest.sh"

run() { # case threads [extra args]
    local dir=$1 threads=$2
    shift 2
    OMP_NUM_THREADS=$threads "$solver" -case "$dir" "$@" >"$dir/log.mpmFoam.$threads" 2>&1 ||
        { echo "FAIL: mpmFoam failed on $dir"; cat "$dir/log.mpmFoam.$threads"; exit 1; }
}

for c in restart2D restart3D restartBodies2D bodyContact2D sdemBodies2D vibratedBlock2D viscoelastic2D slipWalls2D sdemBlock2D splitting2D; do
    src=$root/tests/cases/$c
    for t in 1 2; do
        rm -rf "$work/$c.$t" && cp -r "$src" "$work/$c.$t"
        run "$work/$c.$t" "$t"
    done
    n=0
    for f in "$work/$c.1"/[0-9]*/particles.vtu; do
        rel=${f#"$work/$c.1/"}
        if cmp -s "$f" "$work/$c.2/$rel"; then n=$((n + 1)); else
            echo "FAIL: $c: $rel differs between 1 and 2 threads"; fail=1; fi
    done
    cmp -s "$work/$c.1/postProcessing/energy/0/energy.dat" "$work/$c.2/postProcessing/energy/0/energy.dat" ||
        { echo "FAIL: $c: energy.dat differs between 1 and 2 threads"; fail=1; }
    echo "$c: $n time directories bit-identical with 1 and 2 threads"
    if [[ $c == vibratedBlock2D ]]; then
        # A time-varying g: kinetic + strain − W (W: the work of g, column 4 is −W) stays near its
        # start, within 5 % of the largest kinetic + strain energy (FLIP dissipation and impacts).
        awk '!/^#/ {e = $2 + $3; if (e > m) m = e; d = $5 < 0 ? -$5 : $5; if (d > w) w = d}
             END {printf "vibratedBlock2D: energy balance |E_k + E_s - W| <= %.3g J of %.3g J\n", w, m
                  exit !(m > 0.1 && w <= 0.05 * m)}' "$work/$c.2/postProcessing/energy/0/energy.dat" ||
            { echo "FAIL: vibratedBlock2D: the energy balance with a time-varying g is off"; fail=1; }
    fi

    # Restart: stop at T/2, then resume to T.
    half=$work/$c.half
    rm -rf "$half" && cp -r "$src" "$half"
    end=$(sed -n 's/^endTime: *//p' "$src/system/controlDict")
    mid=$(sed -n 's/^writeInterval: *//p' "$src/system/controlDict")
    sed -i "s/^endTime:.*/endTime: $mid/" "$half/system/controlDict"
    run "$half" 2
    sed -i "s/^endTime:.*/endTime: $end/" "$half/system/controlDict"
    run "$half" 2
    grep -q "Restart from time" "$half/log.mpmFoam.2" || { echo "FAIL: $c: second run did not restart"; fail=1; }
    if [[ -f $src/constant/bodyContact ]] && ! grep -q '\[\[' "$half/$mid/uniform/bodyContacts"; then
        echo "FAIL: $c: no body contact history at the restart time $mid (the test would prove nothing)"; fail=1
    fi
    if [[ $c == slipWalls2D ]] && ! grep -q '^nodes: \[[0-9]' "$half/$mid/uniform/wallContact"; then
        echo "FAIL: $c: no wall contact stored at the restart time $mid (the test would prove nothing)"; fail=1
    fi
    if [[ $c == viscoelastic2D ]]; then # the restart must carry a non-zero stored σᵉ
        "$py" - "$half/$mid/particles.vtu" <<'PY' || { echo "FAIL: $c: no flowing point with a stored elastic stress at $mid (the test would prove nothing)"; fail=1; }
import sys, vtk
from vtk.util.numpy_support import vtk_to_numpy
r = vtk.vtkXMLUnstructuredGridReader()
r.SetFileName(sys.argv[1])
r.Update()
d = r.GetOutput().GetPointData()
sys.exit(not ((vtk_to_numpy(d.GetArray("flowState")) == 1).any() and
              abs(vtk_to_numpy(d.GetArray("elasticStress"))).max() > 0))
PY
    fi
    if [[ $c == sdemBlock2D ]]; then # the restart must carry non-zero tangential springs
        "$py" - "$half/$mid/particles.vtu" <<'PY' || { echo "FAIL: $c: no point with a stored tangential spring at $mid (the test would prove nothing)"; fail=1; }
import sys, vtk
from vtk.util.numpy_support import vtk_to_numpy
r = vtk.vtkXMLUnstructuredGridReader()
r.SetFileName(sys.argv[1])
r.Update()
sys.exit(not (abs(vtk_to_numpy(r.GetOutput().GetPointData().GetArray("contactSlip"))) > 0).any())
PY
    fi
    if [[ $c == splitting2D ]]; then # points split before the restart time and after it
        "$py" - "$half" "$mid" <<'PY' || { echo "FAIL: $c: no split before or after $mid (the test would prove nothing)"; fail=1; }
import os, sys, vtk
def points(t):
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(os.path.join(sys.argv[1], t, "particles.vtu"))
    r.Update()
    return r.GetOutput().GetNumberOfPoints()
times = sorted((d for d in os.listdir(sys.argv[1]) if d[0].isdigit()), key=float)
n0, nMid, nEnd = points(times[0]), points(sys.argv[2]), points(times[-1])
print("splitting2D: %d points at 0, %d at the restart time, %d at the end" % (n0, nMid, nEnd))
sys.exit(not n0 < nMid < nEnd)
PY
    fi
    last=$(ls -d "$work/$c.2"/[0-9]* | xargs -n1 basename | sort -g | tail -1)
    if cmp -s "$work/$c.2/$last/particles.vtu" "$half/$last/particles.vtu"; then
        echo "$c: restarted run matches the uninterrupted run at t = $last (bit-identical)"
    else
        echo "FAIL: $c: restarted run differs from the uninterrupted one at t = $last"; fail=1
    fi

    "$py" - "$work/$c.2" <<'PY' || fail=1
import sys, os, xml.etree.ElementTree as ET
import vtk
case = sys.argv[1]
entries = ET.parse(os.path.join(case, "particles.pvd")).getroot().find("Collection").findall("DataSet")
assert len(entries) >= 3, "expected 3 entries in particles.pvd"
for e in entries:
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(os.path.join(case, e.get("file")))
    r.Update()
    o = r.GetOutput()
    n = o.GetNumberOfPoints()
    assert n > 0 and o.GetNumberOfCells() == n, "every particle needs a VTK_VERTEX cell"
    assert all(o.GetCellType(i) == vtk.VTK_VERTEX for i in range(0, n, max(1, n // 50)))
    for name in ("id", "velocity", "stress", "pressure", "density", "volume", "material", "plasticStrain"):
        assert o.GetPointData().GetArray(name) is not None, "missing array " + name
bodies = os.path.join(case, "rigidBodies.pvd")
if os.path.exists(bodies):
    for e in ET.parse(bodies).getroot().find("Collection").findall("DataSet"):
        r = vtk.vtkXMLPolyDataReader()
        r.SetFileName(os.path.join(case, e.get("file")))
        r.Update()
        o = r.GetOutput()
        assert o.GetNumberOfPoints() > 0 and o.GetNumberOfCells() > 0, "empty rigidBodies.vtp"
        assert o.GetCellData().GetArray("body") is not None
    print("%s: VTK readers load rigidBodies.pvd and every rigidBodies.vtp" % os.path.basename(case))
print("%s: VTK readers load particles.pvd (%d steps) and every particles.vtu" % (os.path.basename(case), len(entries)))
PY
done
exit $fail
