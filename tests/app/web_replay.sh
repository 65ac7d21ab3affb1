#!/bin/bash
# A recording downloaded from the console replays on another machine: on a 2-rank headless wall
# (--web-port) playing a scene that derives from another (both in a folder of their own), a path
# and an OpenEXR movie are recorded while the camera is steered, then downloaded: the path (GET
# /recordings/flight.toml) into another folder, the movie as a zip (GET /movies/live). The scenes'
# folder is renamed away: the recording's download is then refused (500, naming the missing scene)
# and the wall goes on; it quits. The recorded file, which names its base, no longer reads; the downloaded copy, its base scenes embedded, is rendered offline on 2 ranks: every
# frame of the downloaded movie comes back bit-identical at its time (the EXRs with 0 half-float ulps).
source "$(dirname "$0")/lib.sh"
command -v curl >/dev/null || { echo "SKIP: curl is not installed"; exit 77; }

scenes="$WORK/scenes"
mkdir -p "$scenes" "$WORK/out" "$WORK/elsewhere"
cp "$SCENE" "$scenes/live.toml"
printf '[scene]\nbase = "live.toml"\nname = "derived"\n\n[aurora]\nstep_km = 4.0\n' > "$scenes/derived.toml"
out="$WORK/out"
SCENE="$scenes/derived.toml" start_web_wall "$out" --dt 0.25 --start-time 100
check() { "$@" || { stop_wall; cat "$WORK/log"; fail "$*"; }; }
post() {
    curl -s --data-binary "$1" "$url/command" > "$WORK/body"
    echo "$1 -> $(cat "$WORK/body")" >&2
    cat "$WORK/body"
}
frame() { curl -s "$url/status" | python3 -c 'import json, sys; print(json.load(sys.stdin)["frame"])'; }
frames() {
    local start; start=$(frame)
    for _ in $(seq 300); do
        [ $(( $(frame) - start )) -ge "$1" ] && return 0
        sleep 0.1
    done
    stop_wall; fail "the wall drew fewer than $1 frames in 30 s"
}

note "record a path and a movie while steering"
check grep -qx "ok record start $out/flight.toml" <(post "record start flight.toml")
check grep -qx "ok movie start $out/live" <(post "movie start exr live")
check grep -q '^ok goto ' <(post "goto 65 25 200")
frames 3
check grep -q '^ok look ' <(post "look 30 20")
frames 3
check grep -q "^ok movie stop $out/live frames=" <(post "movie stop")
check grep -q "^ok record stop $out/flight.toml keys=" <(post "record stop")

note "download both, then quit"
copy="$WORK/elsewhere/flight.toml"
check [ "$(curl -s -o "$copy" -w '%{http_code}' "$url/recordings/flight.toml")" = 200 ]
check [ "$(curl -s -o "$WORK/live.zip" -w '%{http_code}' "$url/movies/live")" = 200 ]

note "the scenes renamed away: the recording can no longer be downloaded, the wall goes on"
mv "$scenes" "$WORK/scenes-gone"
code=$(curl -s -o "$WORK/body" -w '%{http_code}' "$url/recordings/flight.toml")
echo "GET /recordings/flight.toml -> $code $(cat "$WORK/body")"
check [ "$code" = 500 ]
check grep -q "^error recording flight.toml: .*/scenes/derived.toml: the base scene cannot be read" "$WORK/body"
frames 2
check grep -qx 'ok quit' <(post quit)
status=0; wait $job || status=$?
[ $status -eq 0 ] || { cat "$WORK/log"; fail "the wall exited $status"; }
grep -q '^base = ' "$copy" && fail "the downloaded recording still names a base scene"
head -n 12 "$copy"

wall="$WORK/tiny-2-ranks.toml"
aw_mpirun 2 render --wall "$wall" --scene "$out/flight.toml" --frames 1 --quiet --out "$WORK/x" > "$WORK/x-log" 2>&1 &&
    fail "the recorded file read without its base scene"
grep -q 'live.toml\|derived.toml' "$WORK/x-log" || { cat "$WORK/x-log"; fail "no error naming the missing base scene"; }

python3 - "$WORK/live.zip" "$WORK/unzipped" <<'PY' || fail "the movie's zip"
import sys, zipfile
with zipfile.ZipFile(sys.argv[1]) as z:
    assert z.testzip() is None
    z.extractall(sys.argv[2])
    print(f"the movie's zip: {len(z.namelist())} files")
PY
live="$WORK/unzipped/live"
last=$(tail -n 1 "$live/frames.csv" | cut -d, -f1)
n=$(ls "$live"/frame-*.exr | wc -l)
[ "$n" -ge 6 ] || fail "only $n movie frames"
note "replay the downloaded copy offline: frames 0 to $last"
aw_mpirun 2 render --wall "$wall" --scene "$copy" --frames $((last + 1)) --quiet \
    --movie "$WORK/replayed" --movie-exr --out "$WORK/replay-out" > "$WORK/replay-log" 2>&1 ||
    { cat "$WORK/replay-log"; fail "the downloaded recording did not replay"; }
# The copy starts at the time `record start` was asked at: the frames are matched by their times.
python3 - "$live/frames.csv" "$WORK/replayed/frames.csv" > "$WORK/pairs" <<'PY' || fail "the frames' times"
import sys
def times(path):
    with open(path) as f:
        return {t: int(n) for n, t in (line.strip().split(",") for line in f.readlines()[1:])}
live, replayed = times(sys.argv[1]), times(sys.argv[2])
missing = [t for t in live if t not in replayed]
assert not missing, f"live frames at times {missing} are not in the replay"
for t, n in sorted(live.items(), key=lambda kv: kv[1]):
    print(f"frame-{n:06d}.exr frame-{replayed[t]:06d}.exr")
PY
while read -r flown again; do
    "$COMPARE" diff "$live/$flown" "$WORK/replayed/$again" --half-ulps 0 > "$WORK/diff" ||
        { cat "$WORK/diff"; fail "$flown differs from the replay's $again"; }
done < "$WORK/pairs"
[ "$(wc -l < "$WORK/pairs")" = "$n" ] || fail "$(wc -l < "$WORK/pairs") pairs for $n frames"
"$COMPARE" diff "$live/frame-$(printf %06d "$last").exr" "$(ls "$live"/frame-*.exr | head -n 1)" --half-ulps 0 > /dev/null &&
    fail "the steering did not change the picture"
note "all $n downloaded movie frames replayed bit-identical from the downloaded recording"
echo "PASS web_replay"
