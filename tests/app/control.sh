#!/bin/bash
# Remote control: a 2-rank headless wall with --control-port 0 --frames 0 answers status, pause,
# time, goto, preset, orbit, screenshot and quit through launch/wall-control; a garbage line, an out-of-range value,
# a second client at once and a client that leaves mid-line get their answers (or none) and the
# wall keeps rendering; the screenshots differ after goto; the job exits 0 soon after quit; and
# every rank drew every frame at the master's frame and time (--stats).
source "$(dirname "$0")/lib.sh"

# The tiny 2x2 wall driven by two ranks, two screens each.
wall="$WORK/tiny-2-ranks.toml"
{ cat "$DATA/tiny-2x2.toml"; printf '\n[ranks]\nscreens_per_rank = 2\n'; } > "$wall"

aw_mpirun 2 render --wall "$wall" --scene "$SCENE" --frames 0 --control-port 0 --quiet \
    --out "$WORK" --stats "$WORK/s.csv" > "$WORK/log" 2>&1 &
job=$!
port=$(control_port "$WORK/log" "$job")
note "wall on port $port"

# ask EXPECTED COMMAND...: the commands through the client; the last answer must match the regex
# EXPECTED, and the client exits 0 if every answer is ok, 1 otherwise.
ask() {
    local expected="$1" answers code=0; shift
    answers=$("${client[@]}" --port "$port" "$@") || code=$?
    echo "$* -> $answers"
    [[ "$(tail -n 1 <<<"$answers")" =~ $expected ]] ||
        { kill $job; fail "'$*' answered '$answers', expected /$expected/"; }
    grep -qv '^ok' <<<"$answers" && want=1 || want=0
    [ $code -eq $want ] || { kill $job; fail "wall-control exited $code after '$answers', expected $want"; }
}
number='-?[0-9.e+-]+'

ask "^ok frame=[0-9]+ time_s=$number fps=$number playing speed=1 lat_deg=$number lon_deg=$number alt_km=$number heading_deg=$number pitch_deg=$number\$" status
ask "^ok paused at time_s=$number\$" pause
ask '^ok time_s=120$' "time 120"
ask '^ok screenshot .*/before\.png$' "screenshot before.png"
ask ' time_s=120 fps=[0-9.e+-]+ paused ' status
ask '^ok goto lat_deg=65 lon_deg=25 alt_km=200$' "goto 65 25 200"
ask ' time_s=120 .* lat_deg=65\.000000 lon_deg=25\.000000 alt_km=200\.000000 ' status
ask '^ok screenshot .*/after\.png$' "screenshot after.png"
# A preset moves the camera to its scene's (ground-65n: 65 N 20 E, 300 m up), by name or by file;
# an unknown one is refused and the camera stays.
ask '^ok preset ground-65n lat_deg=65\.000000 lon_deg=20\.000000 alt_km=0\.300000$' "preset ground-65n"
ask ' time_s=120 .* lat_deg=65\.000000 lon_deg=20\.000000 alt_km=0\.300000 heading_deg=(0|360)\.000000 pitch_deg=30\.000000$' status
ask '^error preset nowhere: no such preset in .* \(presets: .*low-orbit.*\)$' "preset nowhere"
ask '^ok preset .*/low-orbit\.toml lat_deg=58\.000000 lon_deg=20\.000000 alt_km=400\.000000$' \
    "preset $SRC_DIR/config/scenes/low-orbit.toml"
ask ' lat_deg=58\.000000 lon_deg=20\.000000 alt_km=400\.000000 ' status
# Bytes that are not UTF-8 reach the wall as they are, from the command line and from stdin, and get
# its one-line error; a preset nested past the config limit is refused and the wall keeps running.
ask "^error unknown command 'caf.*' \\(commands: " $'caf\xe9'
answer=$(printf '\xff\xfe\nstatus\n' | "${client[@]}" --port "$port") && { kill $job; fail "stdin bytes: exit 0"; }
[[ "$answer" =~ ^error\ unknown\ command.*$'\n'ok\ frame= ]] || { kill $job; fail "stdin bytes answered '$answer'"; }
python3 -c "print('[scene]\nname = \"d\"\ncomponents = [\"planet\"]\n[planet]\nradius_km = ' + '[' * 20000 + '1' + ']' * 20000)" \
    > "$WORK/deep.toml"
ask "^error preset .*deep\.toml:5: arrays and inline tables nested more than 64 deep" "preset $WORK/deep.toml"
ask ' lat_deg=58\.000000 lon_deg=20\.000000 alt_km=400\.000000 ' status
# A large preset is read off the frame loop: while a chain of base scenes, each with curtains of
# 16,000, 16,000 and 10,000 points (within the limits of an array and a file), is read (seconds),
# status answers and the
# frames go on, and a second preset is refused; then the chain's last base, one curtain of 400,000
# points, is refused for its length before it is parsed, and the camera stays.
python3 - "$WORK" <<'PY'
import sys
folder = sys.argv[1]
def curtain(n, lat):
    points = ", ".join(f"[{lat + (k % 100) / 200:.5f}, {-10 + 60 * k / n:.6f}]" for k in range(n))
    return f"[[aurora.curtain]]\npoints_lat_lon_deg = [{points}]\n"
open(f"{folder}/big-7.toml", "w").write('[scene]\nbase = "overhead.toml"\n\n' + curtain(400000, 66))
for level in range(7):
    name = "big.toml" if level == 0 else f"big-{level}.toml"
    open(f"{folder}/{name}", "w").write(f'[scene]\nbase = "big-{level + 1}.toml"\n\n' + curtain(16000, 66) +
                                        curtain(16000, 67) + curtain(10000, 68))
PY
cp "$DATA/overhead.toml" "$WORK/overhead.toml"
"${client[@]}" --port "$port" "preset $WORK/big.toml" > "$WORK/big.answer" &
loader=$!
sleep 0.5 # the preset has reached the wall
frame_before=$(field frame "$("${client[@]}" --port "$port" status)")
ask '^error preset ground-65n: another preset is still loading$' "preset ground-65n"
frame_during=$(field frame "$(ask ' lat_deg=58\.000000 lon_deg=20\.000000 alt_km=400\.000000 ' status)")
kill -0 $loader 2>/dev/null || fail "the big preset was answered before status: $(cat "$WORK/big.answer")"
[ "$frame_during" -gt "$frame_before" ] || fail "no frame was drawn while the preset loaded ($frame_before, $frame_during)"
wait $loader && fail "the big preset was accepted: $(cat "$WORK/big.answer")"
grep -q '^error preset .*/big\.toml: .*/big-7\.toml:5: an array of more than 16384 elements' "$WORK/big.answer" ||
    fail "the big preset answered '$(cat "$WORK/big.answer")'"
note "status answered and frames $frame_before..$frame_during drawn while the big preset loaded"
ask ' lat_deg=58\.000000 lon_deg=20\.000000 alt_km=400\.000000 ' status
# A time jump takes a flying camera (the benchmark view's, 25.484 km/s) no farther than goto may.
ask '^error time: the camera, flying at 25\.484 km/s, would be 2\.55e\+16 km above the ground \(at most 1e6 km, as for goto\)$' \
    "preset benchmark-view" "time 1e15"
ask '^ok time_s=120$' "time 120"
ask '^ok preset .*/low-orbit\.toml ' "preset $SRC_DIR/config/scenes/low-orbit.toml"
# Orbiting a point on the ground 2 degrees north of the camera: the camera stays, turns to look at it
# (the heading north, the pitch down), at the chord's distance; orbit off keeps the pose.
ask '^ok orbit lat_deg=60 lon_deg=20 alt_km=0 distance_km=[0-9.]+$' "orbit 60 20 0"
ask ' lat_deg=58\.000000 lon_deg=20\.000000 alt_km=400\.000000 heading_deg=(0|360)\.000000 pitch_deg=-[0-9.]+$' status
orbit_pitch=$("${client[@]}" --port "$port" status | sed -n 's/.* pitch_deg=//p')
ask '^ok orbit off$' "orbit off"
ask '^error orbit: the altitude must be in \[0, 1e6\] km$' "orbit 60 20 -5"
ask "^error unknown command 'xyzzy' \(commands: .* preset orbit " "xyzzy 1 2 3"
ask '^error speed: the factor must be in \[0\.1, 1000\]$' "speed 5000"
ask '^error step: the clock is playing \(pause first\)$' play step
ask '^error screenshot .*: the file name must end in \.png$' "screenshot x.jpg"
ask '^error screenshot /tmp/x\.png: an absolute path; give a path inside the output folder' "screenshot /tmp/x.png"
ask "^error screenshot \.\./x\.png: '\.\.' would leave the output folder" "screenshot ../x.png"
ask "^error screenshot a/\.\./\.\./x\.png: '\.\.' would leave the output folder" "screenshot a/../../x.png"
ask '^ok paused' pause
ask '^ok goto lat_deg=65 lon_deg=25 alt_km=200$' "goto 65 25 200"

# One client sends half a line and leaves; another holds a connection open while a third asks.
exec 3<>"/dev/tcp/127.0.0.1/$port"
exec 4<>"/dev/tcp/127.0.0.1/$port"
printf 'goto 10 10' >&3
exec 3>&-
printf 'status\n' >&4
ask ' paused .* lat_deg=65\.000000 ' status # the half goto was not carried out
read -r -t 30 held <&4 || fail "no answer on the held connection"
echo "held connection -> $held"
[[ "$held" =~ ^ok\ frame= ]] || fail "held connection answered '$held'"
exec 4>&-

# The pitch toward the orbited point: 400 km above 58 N looking at the ground at 60 N 20 E, from the
# triangle of the planet's centre, the camera and the point (central angle 2 degrees).
awk -v p="$orbit_pitch" 'BEGIN {
    pi = atan2(0, -1); R = 6371; r = R + 400; g = 2 * pi / 180
    x = R * cos(g) - r; y = R * sin(g) # the point in the camera'"'"'s vertical plane: up, north
    expected = atan2(x, y) * 180 / pi
    printf "orbit pitch %.6f deg, expected %.6f\n", p, expected
    if (p - expected > 1e-5 || expected - p > 1e-5) { print "FAIL: orbit pitch" > "/dev/stderr"; exit 1 }
}' || { kill $job; fail "the orbit did not aim at the point"; }

[ -s "$WORK/before.png" ] && [ -s "$WORK/after.png" ] || fail "a screenshot is missing"
cmp -s "$WORK/before.png" "$WORK/after.png" && fail "the screenshots before and after goto are the same"
[ -z "$(find "$WORK" -mindepth 1 -name '*.tmp*')" ] || fail "a temporary file of the atomic write was left"

start=$(now)
ask '^ok quit$' quit
for _ in $(seq 300); do kill -0 $job 2>/dev/null || break; sleep 0.1; done
kill -0 $job 2>/dev/null && { kill $job; fail "still running 30 s after quit"; }
status=0; wait $job || status=$?
cat "$WORK/log"
[ $status -eq 0 ] || fail "the job exited $status after quit"
note "exited 0 $(elapsed "$start") s after quit"

# Every rank drew every frame at the master's frame and time; the paused frames show 120 s.
awk -F, '
    function bad(msg) { print "FAIL: s.csv: " msg > "/dev/stderr"; failed = 1; exit 1 }
    NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
    {
        for (r = 0; r < 2; ++r) {
            if ($col["frame_rank" r] != $col["frame"]) bad("row " NR ": rank " r " drew frame " $col["frame_rank" r])
            if ($col["time_s_rank" r] != $col["time_s"]) bad("row " NR ": rank " r " drew time " $col["time_s_rank" r])
        }
        if ($col["time_s"] == 120) ++paused
    }
    END { if (!failed && paused < 3) bad(paused + 0 " frames at 120 s, expected the paused ones (>= 3)") }
' "$WORK/s.csv"
echo "PASS control"
