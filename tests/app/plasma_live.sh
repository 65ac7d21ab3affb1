#!/bin/bash
# The plasma simulated live on the GPU (device = "gpu"): a wall whose ranks each step their own run
# of the simulation to the master's clock equals one screen bit for bit (the curls on both seams of
# a 2x2 wall, and the box); the stats give the plasma's setFrame time on every rank and frame (line
# and JSON), and no plasma figure for a scene without the plasma.
source "$(dirname "$0")/lib.sh"

same_as_one_screen() {
    local scene="$DATA/$1" wall="$WALLS/desktop-2x2.toml" lit="$2" start="$3" dt="$4" name="${1%.toml}"
    note "$name: 4 ranks, 3 frames from $start s every $dt s, against --single-screen on 1 rank at the last"
    aw_mpirun 4 render --wall "$wall" --scene "$scene" --start-time "$start" --dt "$dt" --frames 3 --gather --quiet \
        --out "$WORK/$name-wall"
    aw_mpirun 1 render --wall "$wall" --scene "$scene" --start-time "$(awk "BEGIN { print $start + 2 * $dt }")" \
        --single-screen --gather --quiet --out "$WORK/$name-single"
    "$COMPARE" content "$WORK/$name-wall/wall.exr" "$wall" --min-max 1e-3 --lit-above 5e-4 --min-lit-screens "$lit"
    "$COMPARE" diff "$WORK/$name-single/wall.exr" "$WORK/$name-wall/wall.exr" --half-ulps 0
}

# The wall steps its runs over 3 frames; the single screen jumps straight to the last frame's time.
# The curls: 40, 45, 50 s, stepping forward. The box (frames over 4 s, then again): 2.5, 4.5, 6.5 s,
# steps 19, 4 (back to the start: a restart) and 19 again.
same_as_one_screen plasma-live-seam.toml 2 40 5
same_as_one_screen plasma-box-live-seam.toml 1 2.5 2

note "stats: the plasma's setFrame on a 2x2 wall of tiny screens"
tiny="$DATA/tiny-2x2.toml"
aw_mpirun 4 render --wall "$tiny" --scene "$DATA/plasma-live-seam.toml" --frames 3 --stats "$WORK/plasma.json" \
    --out "$WORK/plasma-stats" >"$WORK/plasma.log"
grep -q "setFrame plasma [0-9.]* ms" "$WORK/plasma.log" || { cat "$WORK/plasma.log" >&2; fail "no 'setFrame plasma' in the frame lines"; }
aw_mpirun 4 render --wall "$tiny" --scene "$DATA/overhead.toml" --frames 2 --stats "$WORK/plain.json" \
    --out "$WORK/plain-stats" >"$WORK/plain.log"
! grep -q "setFrame plasma" "$WORK/plain.log" || fail "a scene without the plasma shows a plasma setFrame"
python3 - "$WORK/plasma.json" "$WORK/plain.json" <<'PY'
import json, sys
def ranks(path):
    return [r for f in json.load(open(path))["frames"] for r in f["ranks"]]
live = ranks(sys.argv[1])
assert len(live) == 12, f"{len(live)} rank reports, expected 3 frames x 4 ranks"
for i, r in enumerate(live):
    ms = r["component_ms"]["plasma"]
    assert ms >= 0.0, f"plasma setFrame {ms} ms"
    # Frame 0 always steps the run and deposits its first frame: it takes time on every rank.
    assert i >= 4 or ms > 0.0, f"frame 0: plasma setFrame {ms} ms"
    assert r["component_ms"]["plasma"] <= r["prepare_ms"], "a component's share exceeds the rank's prepare time"
plain = ranks(sys.argv[2])
assert all("plasma" not in r["component_ms"] and "aurora" in r["component_ms"] for r in plain), \
    "the scene without plasma: no plasma figure, an aurora one"
print("plasma setFrame ms (frame 0, every rank):", [round(r["component_ms"]["plasma"], 1) for r in live[:4]])
PY
echo "PASS plasma_live"
