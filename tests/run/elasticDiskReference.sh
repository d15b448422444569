#!/usr/bin/env bash
# bin/tools/elasticDisk.py, the finite-element answer that diskCollision and diskDrop are
# checked against (their READMEs, "The known answer"), on its coarsest mesh (h = 2 mm, a few
# seconds): the neo-Hookean run conserves energy (the integrator), and the hypoelastic runs
# land within 0.003 of the converged values the tutorials use (collision 0.976 v0, drop 0.947
# of the drop energy, both hard; h = 0.5 mm gives 0.9759 and 0.9469).
set -euo pipefail
. "$(dirname "$0")/../tools/scriptTest.sh"

"$py" - "$root/bin/tools" <<'PY' || fail=1
import sys
sys.path.insert(0, sys.argv[1])
import elasticDisk

ok = True
def check(name, good, detail):
    global ok
    print("%s: %s (%s)" % ("PASS" if good else "FAIL", name, detail))
    ok &= good

r = elasticDisk.run("collision", "hard", h=2e-3, law="neoHookean")
check("neo-Hookean collision conserves energy", r["drift"] < 1e-3 and r["separated"],
      "drift %.1e" % r["drift"])
for case, ref in (("collision", 0.976), ("drop", 0.947)):
    r = elasticDisk.run(case, "hard", h=2e-3)
    check("hypoelastic %s within 0.003 of %g" % (case, ref),
          abs(r["result"] - ref) <= 0.003 and r["separated"], "%.4f" % r["result"])
sys.exit(0 if ok else 1)
PY
exit $fail
