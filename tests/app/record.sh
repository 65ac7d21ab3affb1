#!/bin/bash
# --record-path: a 1-rank headless wall steered over TCP (goto, then look) until quit writes the
# flown camera as a scene deriving from the played one; replaying that scene for as many frames at
# the same --dt draws every frame bit-identical to the recorded run (--movie-exr, compared with
# 0 half-float ulps), the gathered walls included. The replay is exact at the recorded frame times,
# where the path has its keys. Then a path that zooms (field_of_view_deg) recorded between its keys:
# the recorded keys carry the zoom and replay bit-identical too.
source "$(dirname "$0")/lib.sh"

wall="$WORK/tiny-1-rank.toml"
{ cat "$DATA/tiny-2x2.toml"; printf '\n[ranks]\nper_screen = [0, 0, 0, 0]\n'; } > "$wall"
mkdir -p "$WORK/paths"
flight="$WORK/paths/flight.toml"

aw_mpirun 1 render --wall "$wall" --scene "$SCENE" --frames 0 --control-port 0 --quiet --dt 0.25 \
    --start-time 100 --record-path "$flight" --movie "$WORK/flown" --movie-exr --gather --out "$WORK/flown-out" \
    > "$WORK/log" 2>&1 &
job=$!
port=$(control_port "$WORK/log" "$job")
sleep 0.3
"${client[@]}" --port "$port" "goto 65 25 200" || { kill $job; fail "goto refused"; }
sleep 0.3
"${client[@]}" --port "$port" "look 30 20" || { kill $job; fail "look refused"; }
sleep 0.3
"${client[@]}" --port "$port" quit || { kill $job; fail "quit refused"; }
status=0; wait $job || status=$?
[ $status -eq 0 ] || { cat "$WORK/log"; fail "the recording run exited $status"; }

[ -s "$flight" ] || fail "no $flight after quit"
head -n 8 "$flight"
grep -q '^base = "\.\./' "$flight" || fail "the base scene is not named relative to the recorded file"
keys=$(grep -c '^\[\[camera\.key\]\]$' "$flight")
frames=$(ls "$WORK/flown"/frame-*.exr | wc -l)
note "$frames frames flown, $keys keys recorded"
[ "$keys" -eq "$frames" ] || fail "$keys keys for $frames frames"
[ "$frames" -ge 3 ] || fail "only $frames frames: the run cannot show goto and look"
[ -z "$(find "$WORK/paths" -name '*.tmp*')" ] || fail "a temporary file of the atomic write was left"

aw_mpirun 1 render --wall "$wall" --scene "$flight" --frames "$frames" --dt 0.25 --quiet \
    --movie "$WORK/replayed" --movie-exr --gather --out "$WORK/replayed-out" > "$WORK/replay-log" 2>&1 ||
    { cat "$WORK/replay-log"; fail "the replay failed"; }
cmp "$WORK/flown/frames.csv" "$WORK/replayed/frames.csv" || fail "the replay's frame times differ"
for f in "$WORK/flown"/frame-*.exr; do
    "$COMPARE" diff "$f" "$WORK/replayed/$(basename "$f")" --half-ulps 0 > "$WORK/diff" ||
        { cat "$WORK/diff"; fail "$(basename "$f") differs in the replay"; }
done
"$COMPARE" diff "$WORK/flown-out/wall.exr" "$WORK/replayed-out/wall.exr" --half-ulps 0 ||
    fail "the gathered walls differ"
# The steering shows: the first and the last frame differ.
"$COMPARE" diff "$WORK/flown/frame-000000.exr" "$WORK/flown-out/wall.exr" --half-ulps 0 > /dev/null &&
    fail "goto and look did not change the picture"
note "all $frames replayed frames identical"

zoomed="$WORK/paths/zoomed.toml"
aw_mpirun 1 render --wall "$wall" --scene "$DATA/zoom-path.toml" --frames 4 --dt 0.75 --quiet \
    --record-path "$zoomed" --movie "$WORK/zoom-flown" --movie-exr > "$WORK/zoom-log" 2>&1 ||
    { cat "$WORK/zoom-log"; fail "the zoomed recording failed"; }
zooms=$(grep -c '^zoom = ' "$zoomed")
[ "$zooms" -eq 4 ] || fail "$zooms zoom keys recorded for 4 zoomed frames"
grep '^zoom = ' "$zoomed"
aw_mpirun 1 render --wall "$wall" --scene "$zoomed" --frames 4 --dt 0.75 --quiet \
    --movie "$WORK/zoom-replayed" --movie-exr > "$WORK/zoom-replay-log" 2>&1 ||
    { cat "$WORK/zoom-replay-log"; fail "the zoomed replay failed"; }
for f in "$WORK/zoom-flown"/frame-*.exr; do
    "$COMPARE" diff "$f" "$WORK/zoom-replayed/$(basename "$f")" --half-ulps 0 > "$WORK/diff" ||
        { cat "$WORK/diff"; fail "zoomed $(basename "$f") differs in the replay"; }
done
# The zoom shows: the path's first frame (zoom about 2) differs from the same pose at the same time unzoomed.
aw_mpirun 1 render --wall "$wall" --scene "$DATA/overhead.toml" --frames 1 --quiet \
    --movie "$WORK/unzoomed" --movie-exr > "$WORK/unzoomed-log" 2>&1 ||
    { cat "$WORK/unzoomed-log"; fail "the unzoomed render failed"; }
"$COMPARE" diff "$WORK/zoom-flown/frame-000000.exr" "$WORK/unzoomed/frame-000000.exr" --half-ulps 0 > /dev/null &&
    fail "the zoom did not change the picture"
note "4 zoomed frames replayed identical"
