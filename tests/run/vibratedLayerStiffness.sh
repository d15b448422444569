#!/usr/bin/env bash
# cases/vibratedLayer/stiffnessCheck: the 2D strip of the vibrated layer [002 §4.5] flies and
# lands the same at E = 2 MPa as at the paper's 200 MPa (centre-of-mass height within
# 0.15 H on average, apex within 5 %), the ground for the stiffness-scaled 3D runs of that case.
# Six cycles, e = 0.3 and 1: about a minute on two cores.
set -euo pipefail
. "$(dirname "$0")/../tools/scriptTest.sh"
"$py" "$root/cases/vibratedLayer/stiffnessCheck" --work "$work" --cycles 6 --moduli 2e6 || fail=1
exit $fail
