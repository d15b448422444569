#!/usr/bin/env bash
# cases/vibratedLayer/analyse, the surface-pattern check of issue 9 [002 §4.5], on synthetic
# surfaces: a square f/2 pattern of wavelength L/2 with noise and raised wall bands is found,
# noise with the same wall bands is not (without the Hann window the wall bands posed as a
# pattern), nor is the square pattern at a random phase each cycle (the ratio tests alone pass
# it: a slosh, not a standing pattern); the phase filter keeps 61 cycles and leaves out an
# off-phase end time (it once cut the rest).
set -euo pipefail
. "$(dirname "$0")/../tools/scriptTest.sh"
"$py" "$root/cases/vibratedLayer/analyse" --selftest || fail=1
exit $fail
