#!/usr/bin/env bash
# A refactor changes no result: run cases to their first written time with two builds of
# mpmFoam and compare every file they write (logs aside), md5 by md5.
#
#   tests/tools/compareOutputs.sh OLD_BIN NEW_BIN CASE...
#
# OLD_BIN, NEW_BIN: folders holding an mpmFoam (a clone of the commit before, built; this
# tree's bin). Each CASE folder is copied twice to a temporary folder, its endTime set to its
# writeInterval (times deltaT where writeControl is timeStep), and run on one thread with each
# build. Prints per case SAME (files, a fingerprint: the first 12 hex digits of the md5 of the
# sorted md5 list) or DIFF and the files that differ; exits 1 if any case differs or fails.
# docs/notes/refactorChecks.md keeps the fingerprints of the refactors.
set -uo pipefail
[ $# -ge 3 ] || { sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }
old=$(cd "$1" && pwd) new=$(cd "$2" && pwd) || exit 2
shift 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive
status=0
fingerprint() { (cd "$1" && find . -type f ! -name 'log*' -print0 | sort -z | xargs -0 md5sum); }
for c in "$@"; do
    for v in old new; do
        d=$work/$v
        rm -rf "$d" && mkdir -p "$d" && cp -R "$c/constant" "$c/system" "$d/"
        [ -d "$c/0" ] && cp -R "$c/0" "$d/"
        dt=$(awk '/^writeInterval:/ {print $2; exit}' "$d/system/controlDict")
        # A write interval in steps (writeControl: timeStep) is that many initial steps of time.
        if grep -q '^writeControl: *timeStep' "$d/system/controlDict"; then
            step=$(awk '/^deltaT:/ {print $2; exit}' "$d/system/controlDict")
            dt=$(awk -v n="$dt" -v s="$step" 'BEGIN {printf "%.12g", n * s}')
        fi
        sed -i "s|^endTime:.*|endTime: $dt|" "$d/system/controlDict"
        bin=$old
        [ $v = new ] && bin=$new
        if ! (cd "$d" && timeout 600 "$bin/mpmFoam" -case . > log 2>&1); then
            echo "FAIL $c: $v build failed ($(tail -1 "$d/log"))"
            status=1
            continue 2
        fi
    done
    a=$(fingerprint "$work/old") b=$(fingerprint "$work/new")
    if [ "$a" = "$b" ]; then
        echo "SAME $c ($(echo "$b" | wc -l) files, $(echo "$b" | md5sum | cut -c1-12))"
    else
        echo "DIFF $c:"
        diff <(echo "$a") <(echo "$b") | sed -n 's/^> [0-9a-f]*  /    /p'
        status=1
    fi
done
exit $status
