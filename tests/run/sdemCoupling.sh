#!/usr/bin/env bash
# The sdem coupling [001 §4.1, Eq. 43–50] on a case (tests/cases/sdemBlock2D): an elastic block
# (0.1 m × 0.05 m, ρ = 2000 kg/m³: W = 98.1 N/m) rests on a fixed box through k_n ξ normal and
# k_t δ_t tangential springs with the Coulomb cap μ = 0.3. Averages over the last 0.02 s of
# 0.06 s (geostatic start, PIC: the first contact ringing has decayed):
#  - flat:   Σ F_n = W within 1 %, Σ F_t and the torque zero (symmetry);
#  - g tilted 10° (tan 10° < μ, stick): the springs hold the block, F_t = W sin 10° and
#    F_n = W cos 10° within 1 %, the block's speed < 1 mm/s;
#  - g tilted 30° (tan 30° > μ, slide): F_t = μ F_n within 1 % (every bottom point at its
#    cap), and the block accelerates at g (sin 30° − μ cos 30°) within 2 %.
set -euo pipefail
. "$(dirname "$0")/../tools/scriptTest.sh"

for tilt in 0 10 30; do
    dir=$work/tilt$tilt
    copy sdemBlock2D "$dir"
    "$py" - "$dir/constant/g" "$tilt" <<'PY'
import math, sys
a = math.radians(float(sys.argv[2]))
open(sys.argv[1], "w").write("value: [%.17g, %.17g]\n" % (9.81 * math.sin(a), -9.81 * math.cos(a)))
PY
    run "$dir" 2
    "$py" - "$dir" "$tilt" <<'PY' || fail=1
import math, sys
import numpy as np
case, tilt = sys.argv[1], float(sys.argv[2])
b = np.loadtxt(case + "/postProcessing/bodies/0/bodies.dat")
c = np.loadtxt(case + "/postProcessing/block/0/block.dat")
W = 2000 * 0.1 * 0.05 * 9.81
a = math.radians(tilt)
late = b[:, 0] >= 0.04
Fx, Fy, Tz = (-b[late, k].mean() for k in (6, 7, 8)) # the force on the block: −F_body
Fn, Ft = Fy, -Fx                                        # the box's top face: n = +y
ok = True
def check(name, value, expected, tol):
    global ok
    good = abs(value - expected) <= tol
    ok &= good
    print("sdemCoupling: tilt %2g: %s = %.6g (expected %.6g, tolerance %.3g)%s"
          % (tilt, name, value, expected, tol, "" if good else "  FAIL"))
if tilt == 0:
    check("F_n/W", Fn / W, 1.0, 0.01)
    check("F_t/W", Ft / W, 0.0, 1e-9)
    check("T/(W·0.05 m)", Tz / (W * 0.05), 0.0, 1e-9)
elif math.tan(a) < 0.3:
    check("F_n/(W cos)", Fn / (W * math.cos(a)), 1.0, 0.01)
    check("F_t/(W sin)", Ft / (W * math.sin(a)), 1.0, 0.01)
    check("|v| [m/s]", np.hypot(c[late, 4], c[late, 5]).max(), 0.0, 1e-3)
else:
    check("F_t/(mu F_n)", Ft / (0.3 * Fn), 1.0, 0.01)
    t, vx = c[late, 0], c[late, 4]
    accel = np.polyfit(t, vx, 1)[0]
    check("a/(g (sin - mu cos))", accel / (9.81 * (math.sin(a) - 0.3 * math.cos(a))), 1.0, 0.02)
sys.exit(0 if ok else 1)
PY
done
exit $fail
