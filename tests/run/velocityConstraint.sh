#!/usr/bin/env bash
# Velocity constraints (constant/velocityConstraints, src/boundary/VelocityConstraints.hpp) on a
# free elastic block (tests/cases/velocityConstraint2D) under g = (3, −9.81) m/s², 20 ms:
#  - `table` + `components: [x]` (USL, FLIP 0.99, 2 threads): every point's v_x = w(t) (the
#    ramp 0 → 0.5 m/s over 10 ms, then 0.5) to 1e-12 at 10 and 20 ms, the centre of mass moved
#    Σ Δt w(t_n+1) = 7.525 mm along x (1e-9; ∫ w dt = 7.5 mm), v_y = −9.81 t of free fall
#    (1e-9: the free component is untouched), and the block unstrained (|σ| < 1e-6 Pa);
#  - `value: [0.2, 0.1]`, all components (USF, PIC, 1 thread): every point's velocity is w
#    exactly, gravity is taken up, the centre moves w t (1e-9), no stress.
set -euo pipefail
. "$(dirname "$0")/../tools/scriptTest.sh"

for variant in table value; do
    dir=$work/$variant
    copy velocityConstraint2D "$dir"
    threads=2
    if [ "$variant" = value ]; then
        threads=1
        printf 'drive:\n  material: block\n  value: [0.2, 0.1]\n' \
            >"$dir/constant/velocityConstraints"
        sed -i 's/^stressUpdate: .*/stressUpdate: USF/; s/^transfer: .*/transfer: pic/' \
            "$dir/system/mpmSchemes"
    fi
    run "$dir" "$threads"
    "$py" - "$dir" "$variant" <<'PY' || fail=1
import sys
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy
case, variant = sys.argv[1], sys.argv[2]
ok = True
def check(name, value, expected, tol):
    global ok
    good = abs(value - expected) <= tol
    ok &= good
    print("velocityConstraint: %s: %s = %.12g (expected %.12g, tolerance %.3g)%s"
          % (variant, name, value, expected, tol, "" if good else "  FAIL"))
def load(t):
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName("%s/%s/particles.vtu" % (case, t))
    r.Update()
    o = r.GetOutput().GetPointData()
    return vtk_to_numpy(o.GetArray("velocity")), vtk_to_numpy(o.GetArray("stress"))
c = np.loadtxt(case + "/postProcessing/block/0/block.dat")
for t in ("0.01", "0.02"):
    v, s = load(t)
    T = float(t)
    if variant == "table":
        check("t = %s: max |v_x - w|" % t, np.abs(v[:, 0] - 0.5).max(), 0.0, 1e-12)
        check("t = %s: v_y / (-9.81 t)" % t, v[:, 1].mean() / (-9.81 * T), 1.0, 1e-9)
    else:
        check("t = %s: max |v - w|" % t, np.abs(v[:, :2] - [0.2, 0.1]).max(), 0.0, 1e-12)
    check("t = %s: max |sigma| [Pa]" % t, np.abs(s).max(), 0.0, 1e-6)
dx, dy = c[-1, 2] - c[0, 2], c[-1, 3] - c[0, 3]
if variant == "table":
    # Each step moves the points by Δt w(t_n+1) (the constraint at the step's end time): over
    # the ramp Σ Δt² (0.5/0.01) n, n = 1…100, then 100 steps at 0.5 m/s.
    exact = 1e-8 * 0.5 / 0.01 * 5050 + 100 * 1e-4 * 0.5
    check("x_com(20 ms) - x_com(0) / (sum of dt w(t_n+1))", dx / exact, 1.0, 1e-9)
else:
    check("centre displacement / (w t), x", dx / (0.2 * 0.02), 1.0, 1e-9)
    check("centre displacement / (w t), y", dy / (0.1 * 0.02), 1.0, 1e-9)
sys.exit(0 if ok else 1)
PY
done
exit $fail
