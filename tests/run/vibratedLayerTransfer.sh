#!/usr/bin/env bash
# cases/vibratedLayer/transferCheck: under pure FLIP the vibrated layer [002 §4.5] flies apart
# into single points (≥ 5 % isolated, and the isolatedPoints function object warns); with 0.5 %
# PIC it stays a continuum (≤ 3 %, no warning). 2D strip, E = 2 MPa, 15 cycles, e = 0.3 and 1:
# about 40 s on two cores.
set -euo pipefail
. "$(dirname "$0")/../tools/scriptTest.sh"
"$py" "$root/cases/vibratedLayer/transferCheck" --work "$work" --cycles 15 || fail=1
exit $fail
