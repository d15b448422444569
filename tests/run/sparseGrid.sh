#!/usr/bin/env bash
# The sparse grid (docs/sparseGrid.md): memory follows the material, not the box.
#  - tests/cases/sparseBox3D, a 12 × 10 × 8 cm Hencky block thrown through a box of 3.2e7 cells
#    (a dense grid: 3.4 GB of node fields), runs in under 400 MB of peak memory;
#  - the same block in a 1 m³ box (125 000 cells) gives bit-identical particle output: the
#    box's size changes nothing the material can see.
set -euo pipefail
. "$(dirname "$0")/../tools/scriptTest.sh"

big=$work/big small=$work/small
copy sparseBox3D "$big"
copy sparseBox3D "$small"
sed -i 's/^bounds: .*/bounds: {min: [0, 0, 0], max: [1, 1, 1]}/' "$small/constant/grid"
# Peak resident memory of the child, from the kernel's accounting.
peak=$("$py" - "$solver" "$big" <<'PY'
import os, resource, subprocess, sys
env = dict(os.environ, OMP_NUM_THREADS="2")
with open(sys.argv[2] + "/log.mpmFoam", "w") as log:
    rc = subprocess.call([sys.argv[1], "-case", sys.argv[2]], stdout=log, stderr=log, env=env)
print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss // 1024 if rc == 0 else -1)
PY
)
[ "$peak" -ge 0 ] || { echo "FAIL: mpmFoam failed on $big"; tail -20 "$big/log.mpmFoam"; exit 1; }
run "$small" 1
grep "Sparse grid" "$big/log.mpmFoam"
echo "peak memory in the 3.2e7-cell box: $peak MiB"
[ "$peak" -lt 400 ] || { echo "FAIL: peak memory $peak MiB >= 400 MiB"; fail=1; }
for t in $(writes "$small"); do
    if ! cmp -s "$small/$t/particles.vtu" "$big/$t/particles.vtu"; then
        echo "FAIL: particles at t = $t differ between the 1 m³ box and the 3.2e7-cell box"
        fail=1
    fi
done
[ "$(writes "$small")" = "$(writes "$big")" ] || { echo "FAIL: different time directories"; fail=1; }
[ "$fail" -eq 0 ] && echo "PASS: sparseGrid"
exit "$fail"
