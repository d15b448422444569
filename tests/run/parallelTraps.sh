#!/usr/bin/env bash
# The parallel workflow's traps (docs/parallel.md), on the smallest case (restart2D: 124 points,
# 36 blocks, 2 ranks; seconds):
#  1. as root, the documented `mpirun --allow-run-as-root` starts (README and docs/parallel.md
#     show it, and `rebalance` in the quick start);
#  2. decomposePar with more subdomains than blocks refuses before writing anything: a non-zero
#     exit, the key, the file and the block count in the message, no processor folder;
#  3. a run killed while writing (processor1's latest time left as its staging folder) resumes
#     with the same command from the latest time every processor holds, says which newer time
#     it ignores, and ends bit-identical to the uninterrupted run; no common time is an error;
#  4. a corrupt or missing file in processor1/ is an error naming processor1/.
set -euo pipefail
. "$(dirname "$0")/../tools/scriptTest.sh"
bin=$root/bin
export OMP_NUM_THREADS=1
asRoot=()
if [ "$(id -u)" = 0 ]; then asRoot=(--allow-run-as-root); fi
mpi() { timeout 120 mpirun "${asRoot[@]}" --oversubscribe -np "$@"; }
die() { echo "FAIL: $*"; exit 1; }
expect() { # expect TEXT LOG
    grep -qF -- "$1" "$2" || { cat "$2"; die "expected '$1' in $(basename "$2")"; }
}

# 1. The documented commands.
grep -qF -- "--allow-run-as-root" "$root/README.md" || die "README.md: no command for root"
grep -qF -- "--allow-run-as-root" "$root/docs/parallel.md" || die "docs/parallel.md: no command for root"
sed -n '/^```sh/,/^```/p' "$root/docs/parallel.md" | head -12 | grep -q "rebalance" ||
    die "docs/parallel.md: the quick start does not show rebalance"

# 2. More subdomains than blocks.
c=$work/tooMany
copy restart2D "$c"
printf "numberOfSubdomains: 100000\nmethod: bisection\n" > "$c/system/decomposeParDict"
if "$bin/decomposePar" -case "$c" > "$work/e1" 2>&1; then die "decomposePar accepted 100000 subdomains"; fi
expect "system/decomposeParDict" "$work/e1"
expect "key 'numberOfSubdomains'" "$work/e1"
expect "only 36 blocks" "$work/e1"
if compgen -G "$c/processor*" > /dev/null; then die "decomposePar wrote processor folders"; fi
echo "decomposePar: 100000 subdomains on 36 blocks refused, nothing written"

# 3. Resume after a kill during a write.
c=$work/killed
copy restart2D "$c"
printf "numberOfSubdomains: 2\nmethod: bisection\n" > "$c/system/decomposeParDict"
"$bin/decomposePar" -case "$c" > "$c/log.decomposePar" 2>&1 || die "decomposePar"
mpi 2 "$solver" -case "$c" -parallel > "$c/log.1" 2>&1 || { tail "$c/log.1"; die "first run"; }
for r in 0 1; do cp "$c/processor$r/0.06/particles.vtu" "$work/uninterrupted$r.vtu"; done
mv "$c/processor1/0.06" "$c/processor1/.0.06.writing" # killed before the rename
mpi 2 "$solver" -case "$c" -parallel > "$c/log.2" 2>&1 || { tail "$c/log.2"; die "resumed run"; }
expect "Resuming from time 0.03" "$c/log.2"
expect "ignoring the newer incomplete time 0.06 (only in processor0)" "$c/log.2"
expect "Restart from time 0.03" "$c/log.2"
for r in 0 1; do
    cmp -s "$work/uninterrupted$r.vtu" "$c/processor$r/0.06/particles.vtu" ||
        die "processor$r/0.06: the resumed run differs from the uninterrupted one"
done
echo "killed while writing 0.06: resumed from 0.03, bit-identical at 0.06"
d=$work/noCommon
cp -r "$c" "$d"
rm -rf "$d/processor1/"[0-9]*
if mpi 2 "$solver" -case "$d" -parallel > "$work/e2" 2>&1; then die "ran without a common time"; fi
expect "no time directory is complete in every processor folder" "$work/e2"
expect "processor1: none" "$work/e2"

# 4. Corrupt and missing files of processor1 (seen by rank 1 alone: the others stop within 10 s).
sed -i 's/^endTime:.*/endTime: 0.09/' "$c/system/controlDict"
printf "value: [0.06\n" > "$c/processor1/0.06/uniform/time"
if mpi 2 "$solver" -case "$c" -parallel > "$work/e3" 2>&1; then die "ran on a corrupt file"; fi
expect "processor1/0.06/uniform/time:" "$work/e3"
rm "$c/processor1/0.06/uniform/time" # the root case's 0.06/uniform/time is no substitute
if mpi 2 "$solver" -case "$c" -parallel > "$work/e4" 2>&1; then die "ran without uniform/time"; fi
expect "processor1/0.06/uniform/time: required file is missing" "$work/e4"
echo "corrupt and missing processor1 files: errors name processor1/"
echo "PASS parallelTraps"
