#!/bin/bash
# Navigation from the windows, under Xvfb: a 2-rank glfw wall (the tiny 2x2 wall, two screens per
# rank) with --control-port; key presses typed with xdotool into a window of the SECOND rank (an
# operator at rank 1's screen) reach the master and fly the camera: Right turns the heading, R climbs,
# a drag upwards with the left button raises the view, O Right Right Right O orbits the point ahead at
# the same altitude and pitch, as `status` shows, and the screenshot changes. Exits 77 (skipped) without xvfb-run or xdotool.
source "$(dirname "$0")/lib.sh"

run_under_xvfb "640x480x24" "$@"

wall="$WORK/tiny-2-ranks.toml"
{ cat "$DATA/tiny-2x2.toml"; printf '\n[ranks]\nscreens_per_rank = 2\n'; } > "$wall"
aw_mpirun 2 render --wall "$wall" --scene "$SCENE" --backend glfw --frames 0 --control-port 0 --quiet \
    --out "$WORK" > "$WORK/log" 2>&1 &
job=$!
port=$(control_port "$WORK/log" "$job")

ask() { "${client[@]}" --port "$port" "$@" || { kill $job; fail "'$*' was not answered ok"; }; }
# field NAME LINE: the value of NAME=... in a status line.

ask pause >/dev/null
before=$(ask status)
echo "before: $before"
ask "screenshot before.png" >/dev/null

# rank 1 drives the screens of row 1; the operator types into r1c0's window.
window=$(xdotool search --name '^aurorawall r1c0$' | head -n 1)
[ -n "$window" ] || { kill $job; fail "no window 'aurorawall r1c0'"; }
xdotool windowfocus --sync "$window"
xdotool key --delay 50 Right Right Right r r r r r

# The master applies them within a frame or two of their arrival.
for _ in $(seq 200); do
    after=$(ask status)
    [ "$(field alt_km "$after")" != "$(field alt_km "$before")" ] &&
        [ "$(field heading_deg "$after")" != "$(field heading_deg "$before")" ] && break
    sleep 0.1
done
sleep 1 # the last presses
keyed=$(ask status)
echo "keys:   $keyed"

# A drag 15 px up inside the 32x18 window: the view follows the pointer, 0.2 degrees a pixel.
xdotool mousemove --window "$window" 16 17 mousedown 1 mousemove --window "$window" 16 2 mouseup 1
after=$(status_once_changed pitch_deg "$keyed")
echo "drag:   $after"
ask "screenshot after.png" >/dev/null

# O, three Right and O: the camera orbits the point ahead of it about that point's zenith, an axis
# through the planet's centre, so its altitude and pitch stay while it moves across the ground.
xdotool key --delay 50 o Right Right Right o
orbited=$(status_once_changed lon_deg "$after")
echo "orbit:  $orbited"
ask quit >/dev/null
for _ in $(seq 300); do kill -0 $job 2>/dev/null || break; sleep 0.1; done
kill -0 $job 2>/dev/null && { kill $job; fail "still running 30 s after quit"; }
status=0; wait $job || status=$?
[ $status -eq 0 ] || { cat "$WORK/log"; fail "the job exited $status after quit"; }

# Expected from the scene's camera (500 m up, heading 0, pitch 30 degrees): three turns of 2 degrees
# about the camera's up take the heading to atan(sin 6 / (cos 6 cos 30)) = 6.9 degrees; five climbs
# of 0.1 x altitude along the camera's up (cos 30 of it vertical) multiply the altitude by about
# 1.087^5 = 1.5; the drag turns 3 degrees about the camera's right, nearly horizontal.
awk -v h0="$(field heading_deg "$before")" -v h1="$(field heading_deg "$keyed")" \
    -v a0="$(field alt_km "$before")" -v a1="$(field alt_km "$keyed")" \
    -v p1="$(field pitch_deg "$keyed")" -v p2="$(field pitch_deg "$after")" '
    function bad(msg) { print "FAIL: " msg > "/dev/stderr"; exit 1 }
    BEGIN {
        turn = h1 - h0; if (turn < -180) turn += 360
        printf "keys: heading %+.3f deg, altitude x%.4f; drag: pitch %+.3f deg\n", turn, a1 / a0, p2 - p1
        if (turn < 6.0 || turn > 8.0) bad("the heading turned by " turn " degrees, expected about 6.9")
        if (a1 / a0 < 1.3 || a1 / a0 > 1.7) bad("the altitude went from " a0 " to " a1 " km, expected x1.5")
        if (p2 - p1 < 2.5 || p2 - p1 > 3.5) bad("the drag raised the pitch by " p2 - p1 " degrees, expected about 3")
    }'
awk -v a0="$(field alt_km "$after")" -v a1="$(field alt_km "$orbited")" \
    -v p0="$(field pitch_deg "$after")" -v p1="$(field pitch_deg "$orbited")" \
    -v l0="$(field lon_deg "$after")" -v l1="$(field lon_deg "$orbited")" -v t0="$(field lat_deg "$after")" \
    -v t1="$(field lat_deg "$orbited")" '
    function bad(msg) { print "FAIL: " msg > "/dev/stderr"; exit 1 }
    function abs(x) { return x < 0 ? -x : x }
    BEGIN {
        printf "orbit: altitude %+.6f km, pitch %+.6f deg, moved %.3f deg lat %.3f deg lon\n", a1 - a0, p1 - p0, t1 - t0, l1 - l0
        if (abs(a1 - a0) > 2e-6 || abs(p1 - p0) > 2e-6) bad("the orbit changed the altitude or the pitch")
        if (abs(t1 - t0) + abs(l1 - l0) < 0.01) bad("the orbit did not move the camera")
    }'
cmp -s "$WORK/before.png" "$WORK/after.png" && fail "the screenshots before and after the keys are the same"
echo "PASS navigate"
