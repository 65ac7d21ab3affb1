#!/bin/bash
# The heads-up display under Xvfb: a 1-rank glfw wall with --control-port, paused. H typed into the
# window shows the HUD: the window (read back from the X server with ImageMagick's `import`) changes
# only in the HUD's box in the top-left corner and has white text there; the gathered wall
# (`screenshot`) stays byte for byte what it was before, so no file output holds the HUD. A second H
# hides it again. Exits 77 (skipped) without xvfb-run, xdotool or ImageMagick.
source "$(dirname "$0")/lib.sh"
client=(python3 "$SRC_DIR/launch/wall-control")

if [ "${1:-}" != --inside-x ]; then
    if [ -z "${XVFB_RUN:-}" ] || ! [ -x "$XVFB_RUN" ]; then echo "SKIP: xvfb-run is not installed"; exit 77; fi
    for tool in xdotool import convert; do
        command -v $tool >/dev/null || { echo "SKIP: $tool is not installed"; exit 77; }
    done
    exec "$XVFB_RUN" -a -s "-screen 0 1280x1024x24 -noreset" bash "$0" --inside-x
fi

aw_mpirun 1 render --wall "$DATA/hud-1x1.toml" --scene "$SCENE" --backend glfw --frames 0 --control-port 0 \
    --quiet > "$WORK/log" 2>&1 &
job=$!
port=$(control_port "$WORK/log" "$job")
ask() { "${client[@]}" --port "$port" "$@" || { kill $job; fail "'$*' was not answered ok"; }; }

window=$(xdotool search --name '^aurorawall r0c0$' | head -n 1)
[ -n "$window" ] || { kill $job; fail "no window 'aurorawall r0c0'"; }
ask pause >/dev/null
sleep 1 # a few frames of the paused picture
import -window "$window" "$WORK/window-plain.png"
ask "screenshot $WORK/wall-plain.png" >/dev/null

# changed A B: the bounding box WxH+X+Y of the pixels that differ, or nothing if none does.
changed() { convert "$1" "$2" -compose difference -composite -threshold 0 -format "%@" info: 2>/dev/null |
            grep -v '^0x0'; }
# white A: the number of pure white pixels.
white() { convert "$1" -fill black +opaque white -format "%[fx:round(mean*w*h)]" info:; }

xdotool windowfocus --sync "$window"
xdotool key h
for _ in $(seq 100); do
    import -window "$window" "$WORK/window-hud.png"
    box=$(changed "$WORK/window-plain.png" "$WORK/window-hud.png" || true)
    [ -n "$box" ] && break
    sleep 0.1
done
sleep 0.5 # the text settles (the first frames' statistics)
import -window "$window" "$WORK/window-hud.png"
box=$(changed "$WORK/window-plain.png" "$WORK/window-hud.png" || true)
ask "screenshot $WORK/wall-hud.png" >/dev/null
xdotool key h
sleep 1
import -window "$window" "$WORK/window-hidden.png"
ask quit >/dev/null
status=0; wait $job || status=$?
[ $status -eq 0 ] || { cat "$WORK/log"; fail "the job exited $status after quit"; }

echo "HUD box in the window: $box; white pixels: $(white "$WORK/window-plain.png") before, $(white "$WORK/window-hud.png") with the HUD"
[ -n "$box" ] || fail "H did not change the window"
# The box lies in the top-left corner: 8 px from the edges, at most 40 columns x 6 px + 4 wide and
# 24 lines x 9 px + 4 high (render/hud_font.h).
awk -v box="$box" 'BEGIN { split(box, a, /[x+]/);
    if (a[3] < 8 || a[4] < 8 || a[3] + a[1] > 8 + 244 || a[4] + a[2] > 8 + 220) {
        print "FAIL: the window changed outside the HUD box: " box > "/dev/stderr"; exit 1 } }'
[ "$(white "$WORK/window-hud.png")" -gt 200 ] || fail "no white HUD text in the window"
cmp "$WORK/wall-plain.png" "$WORK/wall-hud.png" || fail "the gathered wall changed with the HUD shown"
hidden=$(changed "$WORK/window-plain.png" "$WORK/window-hidden.png" || true)
[ -z "$hidden" ] || fail "the second H left the window changed in $hidden"
mkdir -p "$BUILD_DIR/hud" && cp "$WORK/window-hud.png" "$BUILD_DIR/hud/window-hud.png"
echo "PASS hud"
