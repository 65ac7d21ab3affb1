#!/bin/bash
# The heads-up display under Xvfb: a 1-rank glfw wall with --control-port, paused. H typed into the
# window shows the HUD: the window (read back from the X server, window_pixels.py) changes only in
# the HUD's box in the top-left corner and has white text there; the gathered wall (`screenshot`)
# stays byte for byte what it was before, so no file output holds the HUD. A second H hides it
# again. Exits 77 (skipped) without xvfb-run or xdotool.
source "$(dirname "$0")/lib.sh"

run_under_xvfb "1280x1024x24" "$@"

aw_mpirun 1 render --wall "$DATA/hud-1x1.toml" --scene "$SCENE" --backend glfw --frames 0 --control-port 0 \
    --out "$WORK" --quiet > "$WORK/log" 2>&1 &
job=$!
port=$(control_port "$WORK/log" "$job")
ask() { "${client[@]}" --port "$port" "$@" || { kill $job; fail "'$*' was not answered ok"; }; }

window=$(xdotool search --name '^aurorawall r0c0$' | head -n 1)
[ -n "$window" ] || { kill $job; fail "no window 'aurorawall r0c0'"; }
grab() { python3 "$HERE/window_pixels.py" "$window" "$WORK/$1.ppm"; }
# compare A B: "X0 Y0 X1 Y1 WHITE", the box of the pixels that differ ("none") and B's white pixels.
compare() { python3 "$HERE/ppm_diff.py" "$WORK/$1.ppm" "$WORK/$2.ppm"; }

ask pause >/dev/null
sleep 1 # a few frames of the paused picture
grab plain
ask "screenshot wall-plain.png" >/dev/null

xdotool windowfocus --sync "$window"
xdotool key h
for _ in $(seq 100); do
    grab hud
    [[ "$(compare plain hud)" != none* ]] && break
    sleep 0.1
done
sleep 0.5 # the text of a few more frames
grab hud
shown=$(compare plain hud)
ask "screenshot wall-hud.png" >/dev/null
xdotool key h
sleep 1
grab hidden
hidden=$(compare plain hidden)
ask quit >/dev/null
status=0; wait $job || status=$?
[ $status -eq 0 ] || { cat "$WORK/log"; fail "the job exited $status after quit"; }

echo "with the HUD, changed box (x0 y0 x1 y1) and white pixels: $shown; hidden again: $hidden"
# The box lies in the top-left corner: 8 px from the edges, at most 40 columns x 6 px + 4 wide and
# 24 lines x 9 px + 4 high (render/hud_font.h), and has white text.
awk -v r="$shown" 'BEGIN { n = split(r, a, " ");
    if (n != 5) { print "FAIL: H did not change the window" > "/dev/stderr"; exit 1 }
    if (a[1] < 8 || a[2] < 8 || a[3] > 8 + 244 || a[4] > 8 + 220) {
        print "FAIL: the window changed outside the HUD box: " r > "/dev/stderr"; exit 1 }
    if (a[5] < 200) { print "FAIL: only " a[5] " white pixels with the HUD" > "/dev/stderr"; exit 1 } }'
cmp "$WORK/wall-plain.png" "$WORK/wall-hud.png" || fail "the gathered wall changed with the HUD shown"
[[ "$hidden" == none* ]] || fail "the second H left the window changed: $hidden"
mkdir -p "$BUILD_DIR/hud" && cp "$WORK/hud.ppm" "$BUILD_DIR/hud/window-hud.ppm"
echo "PASS hud"
