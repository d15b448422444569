#!/usr/bin/env bash
# The user guide's quick start runs as written (docs/userGuide.md, the ```sh block after the
# `<!-- quickstart -->` marker), so that the guide and the code cannot drift apart:
#  - the block is taken from the guide (one marker, one fenced sh block after it); every
#    command in it runs, in order, in one bash shell started at the repository root (where the
#    guide says to type them), with pipefail; lines ending in '\' continue the command;
#  - the first command that fails stops the test, naming the command and its exit status;
#  - TMPDIR points into this test's own temporary folder, so the block's `mktemp -d` (its
#    scratch run directory) lands there and is removed afterwards; the run must have written
#    its case there (particles.pvd, postProcessing/).
set -euo pipefail
root=${MPMFOAM_DIR:-$(cd "$(dirname "$0")/../.." && pwd)}
guide=$root/docs/userGuide.md
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

fail() {
    echo "FAIL: $*"
    exit 1
}
[ -f "$guide" ] || fail "$guide not found"
markers=$(grep -c '^<!-- quickstart -->$' "$guide" || true)
[ "$markers" = 1 ] || fail "docs/userGuide.md has $markers '<!-- quickstart -->' markers (expected 1)"

# The block: the first ```sh fence after the marker, up to its closing fence.
awk '/^<!-- quickstart -->$/ { m = 1; next }
     m == 1 && /^```sh$/ { m = 2; next }
     m == 2 && /^```$/ { m = 3; exit }
     m == 2 { print }
     END { if (m != 3) exit 1 }' "$guide" >"$work/block" ||
    fail "no complete \`\`\`sh block after the '<!-- quickstart -->' marker"

# One command per entry (NUL-separated): blank and comment-only lines dropped, continuation
# lines joined.
awk 'BEGIN { cmd = "" }
     { line = $0 }
     cmd == "" && (line ~ /^[[:space:]]*$/ || line ~ /^[[:space:]]*#/) { next }
     line ~ /\\$/ { cmd = cmd substr(line, 1, length(line) - 1) "\n"; next }
     { printf "%s%s%c", cmd, line, 0; cmd = "" }
     END { if (cmd != "") printf "%s%c", cmd, 0 }' "$work/block" >"$work/commands"
count=$(tr -cd '\0' <"$work/commands" | wc -c)
[ "$count" -ge 5 ] || fail "the quick start has only $count commands"
echo "userGuideQuickStart: $count commands from docs/userGuide.md"

cat >"$work/runner.sh" <<'RUNNER'
# Runs the commands of $1 in this shell, in order; stops at the first that fails.
set -o pipefail
mapfile -d '' commands <"$1"
for i in "${!commands[@]}"; do
    printf '+ %s\n' "${commands[i]}"
    eval "${commands[i]}"
    rc=$?
    if [ "$rc" -ne 0 ]; then
        printf 'FAIL: quick-start command %d of %d exited with status %d:\n    %s\n' \
            "$((i + 1))" "${#commands[@]}" "$rc" "${commands[i]}"
        exit 1
    fi
done
RUNNER

mkdir "$work/tmp"
start=$(date +%s)
(cd "$root" && TMPDIR=$work/tmp bash "$work/runner.sh" "$work/commands" </dev/null) ||
    fail "the quick start of docs/userGuide.md does not run as written (above)"
echo "userGuideQuickStart: ran in $(($(date +%s) - start)) s"

# It ran in the scratch folder it made under TMPDIR, not in the repository.
pvd=$(find "$work/tmp" -maxdepth 3 -name particles.pvd | head -n 1)
[ -n "$pvd" ] || fail "the quick start wrote no particles.pvd under its mktemp -d folder"
[ -d "$(dirname "$pvd")/postProcessing" ] || fail "the quick start's case has no postProcessing/"
echo "userGuideQuickStart: OK (case $(basename "$(dirname "$pvd")") under TMPDIR)"
