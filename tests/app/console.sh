#!/bin/bash
# The console window under Xvfb: a 2-rank glfw wall (the tiny 2x2 wall, two screens per rank) with
# --console (--exposure 100: no pixel of the sky black). The master opens "aurorawall console", 480 px
# wide at the wall's aspect, showing the wall (no black pixel); H typed into it shows the HUD there;
# Right typed into it turns the master's camera (status). --console without --backend glfw is a
# usage error (2). Exits 77 (skipped) without xvfb-run or xdotool.
source "$(dirname "$0")/lib.sh"

run_under_xvfb "1280x1024x24" "$@"

status=0
"$AW" render --wall "$DATA/hud-1x1.toml" --scene "$SCENE" --console > "$WORK/egl.log" 2>&1 || status=$?
[ $status -eq 2 ] || fail "--console with the egl backend exited $status, expected 2"
grep -q -- "--console needs --backend glfw" "$WORK/egl.log" || fail "no line naming --console: $(cat "$WORK/egl.log")"

wall="$WORK/tiny-2-ranks.toml"
{ cat "$DATA/tiny-2x2.toml"; printf '\n[ranks]\nscreens_per_rank = 2\n'; } > "$wall"
aw_mpirun 2 render --wall "$wall" --scene "$SCENE" --backend glfw --console --exposure 100 --frames 0 --control-port 0 --quiet \
    > "$WORK/log" 2>&1 &
job=$!
port=$(control_port "$WORK/log" "$job")
ask() { "${client[@]}" --port "$port" "$@" || { kill $job; fail "'$*' was not answered ok"; }; }

window=$(xdotool search --name '^aurorawall console$' | head -n 1)
[ -n "$window" ] || { kill $job; fail "no window 'aurorawall console'"; }
size=$(xdotool getwindowgeometry "$window" | sed -n 's/.*Geometry: //p')
position=$(xdotool getwindowgeometry "$window" | sed -n 's/.*Position: \([0-9-]*,[0-9-]*\).*/\1/p')
echo "console window: $size at $position"
# The wall's four windows fill the desktop's top 36 rows; the console opens below them, covering none.
[ "$position" = "0,36" ] || { kill $job; fail "the console opened at $position, expected 0,36 below the wall's windows"; }
ask pause >/dev/null
sleep 1
grab() { python3 "$HERE/window_pixels.py" "$window" "$WORK/$1.ppm"; }
grab plain
# The wall in the console: no pixel black.
python3 - "$WORK/plain.ppm" <<'PY' || { kill $job; fail "the console shows a black window"; }
import sys
data = open(sys.argv[1], "rb").read().split(maxsplit=4)[4]
width = int(open(sys.argv[1], "rb").read().split(maxsplit=4)[1])
dark = [(i // 3 % width, i // 3 // width) for i in range(0, len(data), 3) if data[i:i + 3] == b"\0\0\0"]
lit = len(data) // 3 - len(dark)
print(f"lit console pixels: {lit} of {len(data) // 3}")
if dark:
    print(f"black pixels from {min(dark)} to {max(dark)}")
sys.exit(0 if lit == len(data) // 3 else 1)
PY

before=$(ask status)
xdotool windowfocus --sync "$window"
xdotool key --delay 50 h Right Right
after=$(status_once_changed heading_deg "$before")
grab hud
shown=$(python3 "$HERE/ppm_diff.py" "$WORK/plain.ppm" "$WORK/hud.ppm")
plainWhite=$(python3 "$HERE/ppm_diff.py" "$WORK/hud.ppm" "$WORK/plain.ppm" | awk '{ print $NF }')
ask quit >/dev/null
status=0; wait $job || status=$?
[ $status -eq 0 ] || { cat "$WORK/log"; fail "the job exited $status after quit"; }

echo "heading $(field heading_deg "$before") -> $(field heading_deg "$after"); console changed (box, white pixels): $shown; white pixels before: $plainWhite"
awk -v h0="$(field heading_deg "$before")" -v h1="$(field heading_deg "$after")" 'BEGIN {
    turn = h1 - h0; if (turn < -180) turn += 360
    if (turn < 4 || turn > 5.5) { print "FAIL: Right Right in the console turned by " turn " deg, expected 4.6" > "/dev/stderr"; exit 1 } }'
# Two turns of 2 degrees about the camera's up at pitch 30: atan(sin 4 / (cos 4 cos 30)) = 4.6 degrees.
awk -v r="$shown" -v w0="$plainWhite" 'BEGIN { n = split(r, a, " ");
    if (n != 5 || a[5] < w0 + 200) { print "FAIL: no HUD text in the console: " r ", white before " w0 > "/dev/stderr"; exit 1 } }'
echo "PASS console"
