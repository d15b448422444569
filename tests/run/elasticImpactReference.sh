#!/usr/bin/env bash
# bin/tools/elasticImpact.py, the finite-element answer that diskCollision, diskDrop and
# rodImpact are compared with (their READMEs), on coarse meshes (seconds): the neo-Hookean run
# conserves energy (the integrator), and the hypoelastic runs land within 0.003 of the
# converged values the tutorials use (disk collision 0.976 v0 and drop 0.947 of the drop
# energy, both hard, h = 2 mm; rod 0.864 v0, soft, h = 1 mm; finer meshes: 0.9759, 0.9469,
# 0.8639).
set -euo pipefail
. "$(dirname "$0")/../tools/scriptTest.sh"

"$py" - "$root/bin/tools" <<'PY' || fail=1
import sys
sys.path.insert(0, sys.argv[1])
import elasticImpact

ok = True
def check(name, good, detail):
    global ok
    print("%s: %s (%s)" % ("PASS" if good else "FAIL", name, detail))
    ok &= good

r = elasticImpact.run("collision", "hard", h=2e-3, law="neoHookean")
check("neo-Hookean collision conserves energy", r["drift"] < 1e-3 and r["separated"],
      "drift %.1e" % r["drift"])
for case, material, h, ref in (("collision", "hard", 2e-3, 0.976), ("drop", "hard", 2e-3, 0.947),
                               ("rod", "soft", 1e-3, 0.864)):
    r = elasticImpact.run(case, material, h=h)
    check("hypoelastic %s within 0.003 of %g" % (case, ref),
          abs(r["result"] - ref) <= 0.003 and r["separated"], "%.4f" % r["result"])
sys.exit(0 if ok else 1)
PY
exit $fail
