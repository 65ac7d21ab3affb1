#!/bin/bash
# Outputs on a full disk (a 8 KiB tmpfs; skipped where it cannot be mounted): --tiles on a 4-rank
# wall writes all four tiles or none, fails with one line from the master naming the reason, exit
# status 1, and leaves no staged or temporary file.
source "$(dirname "$0")/lib.sh"
disk="$WORK/disk"
mkdir -p "$disk"
mount -t tmpfs -o size=8k tmpfs "$disk" 2>/dev/null || { echo "SKIP: cannot mount a tmpfs (not root?)"; exit 77; }
trap 'umount "$disk" 2>/dev/null; cleanup' EXIT
mkdir "$disk/out"

status=0
aw_mpirun 4 render --wall "$DATA/tiny-2x2.toml" --scene "$SCENE" --frames 1 --tiles --quiet --out "$disk/out" \
    >"$WORK/stdout" 2>"$WORK/stderr" || status=$?
cat "$WORK/stderr"
[ $status -eq 1 ] || fail "exit status $status on a full disk, expected 1"
lines=$(grep -c '^aurorawall render: ' "$WORK/stderr" || true)
[ "$lines" -eq 1 ] || fail "$lines error lines, expected 1"
grep -q -- '--tiles: the tiles could not be written into .* (No space left on device)' "$WORK/stderr" ||
    fail "the error does not name --tiles and the reason"
[ -z "$(ls -A "$disk/out")" ] || fail "left behind: $(ls -A "$disk/out" | tr '\n' ' ')"
echo "PASS full_disk"
