#!/bin/bash
# Recording from the console: on a 2-rank headless wall (--web-port, no secret), POST /command
# `record start flight.toml`, frames pass while the camera is steered, `record stop`; the file is
# downloaded from GET /recordings/flight.toml (application/toml, one scene with its base embedded;
# other names and paths leaving the folder 404) into another folder, that copy
# replayed with `preset COPY` and `time FROM`, and recorded
# again: every key's position, direction and up come back bit-identical (17 digits). `movie start`/`movie stop`
# write PNG frames and none after the stop, `movie start exr` OpenEXR frames as well; GET /movies/clip
# is refused (409) while it records and is then the folder's files as a zip, byte for byte; a movie
# whose folder is moved away while it records shows its error in GET /status (movie_error) until its
# stop, and its download then answers 410, as does one whose frames were deleted. Bad paths, a second start, a stop with nothing running are
# refused; on a full disk (a small tmpfs, skipped where it cannot be mounted) the commands answer
# errors. The wall keeps drawing throughout, and exits 0 on quit.
source "$(dirname "$0")/lib.sh"
command -v curl >/dev/null || { echo "SKIP: curl is not installed"; exit 77; }

out="$WORK/out"
mkdir -p "$out"
disk="$out/full"
mkdir "$disk"
mounted=0
if mount -t tmpfs -o size=8k tmpfs "$disk" 2>/dev/null; then
    mounted=1
    trap 'umount "$disk" 2>/dev/null; cleanup' EXIT
fi

start_web_wall "$out" --dt 0.25 --start-time 100
check() { "$@" || { stop_wall; cat "$WORK/log"; fail "$*"; }; }

# post LINE: the command's answer line (status 200 checked).
post() {
    local code
    code=$(curl -s -o "$WORK/body" -w '%{http_code}' --data-binary "$1" "$url/command")
    [ "$code" = 200 ] || { stop_wall; fail "POST '$1' -> $code $(cat "$WORK/body")"; }
    echo "$1 -> $(cat "$WORK/body")" >&2
    cat "$WORK/body"
}
status() {
    curl -s "$url/status" | python3 -c 'import json, sys; print(json.load(sys.stdin)[sys.argv[1]])' "$1"
}
# frames N: waits until N more frames have been drawn (the wall keeps running).
frames() {
    local start; start=$(status frame)
    for _ in $(seq 300); do
        [ $(( $(status frame) - start )) -ge "$1" ] && return 0
        sleep 0.1
    done
    stop_wall; fail "the wall drew fewer than $1 frames in 30 s"
}
refused() { check grep -q "^error $2" <(post "$1"); }

note "refusals"
refused "record stop" "record stop: no recording runs"
refused "movie stop" "movie stop: no movie runs"
refused "record start ../x.toml" "record start \.\./x\.toml: '\.\.' would leave the output folder"
refused "record start /tmp/x.toml" "record start /tmp/x\.toml: an absolute path"
refused "record start nowhere/x.toml" "record start nowhere/x\.toml: .*/nowhere is not a folder"
refused "record start x.png" "record start x\.png: the file name must end in \.toml"
refused "record begin x.toml" "record: start or stop expected"
refused "movie start ../m" "movie start \.\./m: '\.\.' would leave the output folder"
refused "movie start nowhere/m" "movie start nowhere/m: .*/nowhere is not a folder"

note "record a flight"
check grep -qx 'ok goto lat_deg=65 lon_deg=25 alt_km=200' <(post "goto 65 25 200")
check grep -qx "ok record start $out/flight.toml" <(post "record start flight.toml")
refused "record start other.toml" "record start other\.toml: a recording into $out/flight\.toml runs"
frames 4
check grep -qx 'ok look heading_deg=30 pitch_deg=20' <(post "look 30 20")
frames 4
answer=$(post "record stop")
read -r keys from to < <(sed -n 's/^ok record stop .*flight\.toml keys=\([0-9]*\) from_s=\(.*\) to_s=\(.*\)$/\1 \2 \3/p' <<< "$answer")
[ -n "$keys" ] && [ "$keys" -ge 8 ] || { stop_wall; fail "record stop answered '$answer'"; }
note "$keys keys from $from s to $to s"
refused "record stop" "record stop: no recording runs"
[ -z "$(find "$out" -name '*.tmp*')" ] || { stop_wall; fail "a temporary file was left"; }

note "download: one self-contained scene (its base embedded), saved elsewhere"
copy="$WORK/downloads/deeper/flight.toml"
mkdir -p "$(dirname "$copy")"
code=$(curl -s -o "$copy" -w '%{http_code} %{content_type}' "$url/recordings/flight.toml")
check [ "$code" = "200 application/toml" ]
check grep -q '^base = ' "$out/flight.toml"
check [ -z "$(grep '^base = ' "$copy")" ]
check grep -q '^\[\[aurora.curtain\]\]$' "$copy" # the base scene's tables
check [ "$(grep -c '^\[\[camera.key\]\]$' "$copy")" = "$keys" ]
for path in /recordings/other.toml /recordings/../flight.toml /recordings/..%2fout%2fflight.toml \
    /recordings/%2e%2e/%2e%2e/etc/passwd /recordings/ /recordings/screenshot.png \
    /screenshots/flight.toml /screenshots/x.png /screenshots/..%2fout%2fflight.toml \
    /movies/flight.toml /movies/clip /movies/..%2fout /movies/%2e%2e/%2e%2e/etc; do
    code=$(curl -s -o "$WORK/body" -w '%{http_code}' --path-as-is "$url$path")
    echo "GET $path -> $code $(cat "$WORK/body")"
    check [ "$code" = 404 ]
done

note "replay: preset the downloaded copy at its first time, recorded again"
check grep -q '^ok paused' <(post pause)
check grep -q "^ok preset $copy " <(post "preset $copy")
check grep -qx "ok time_s=$from" <(post "time $from")
check grep -qx "ok record start $out/replay.toml" <(post "record start replay.toml")
check grep -q '^ok playing' <(post play)
for _ in $(seq 300); do
    python3 -c 'import sys; sys.exit(0 if float(sys.argv[1]) > float(sys.argv[2]) else 1)' "$(status time_s)" "$to" && break
    sleep 0.1
done
check grep -q "^ok record stop $out/replay.toml " <(post "record stop")
check python3 - "$out/flight.toml" "$out/replay.toml" <<'PY'
import sys, tomllib
def keys(path):
    with open(path, "rb") as f:
        return {k["time_s"]: (k["position_km"], k["direction"], k["up"]) for k in tomllib.load(f)["camera"]["key"]}
flown, replayed = keys(sys.argv[1]), keys(sys.argv[2])
missing = [t for t in flown if t not in replayed]
assert not missing, f"times not replayed: {missing}"
differ = [t for t in flown if flown[t][0] != replayed[t][0]]
assert not differ, f"{len(differ)} of {len(flown)} positions differ, first at {differ[0]}: {flown[differ[0]]} vs {replayed[differ[0]]}"
# At a key's time the path gives the key's frame as written (17 digits): bit for bit too.
turned = [t for t in flown if flown[t][1:] != replayed[t][1:]]
assert not turned, f"{len(turned)} of {len(flown)} directions or ups differ, first at {turned[0]}: {flown[turned[0]]} vs {replayed[turned[0]]}"
print(f"{len(flown)} recorded cameras (position, direction, up) replayed bit-identical")
PY
check grep -q '^ok orbit off' <(post "orbit off")

note "movie"
check grep -qx "ok movie start $out/clip" <(post "movie start clip")
refused "movie start clip2" "movie start clip2: a movie into $out/clip runs"
frames 3
code=$(curl -s -o "$WORK/body" -w '%{http_code}' "$url/movies/clip")
check [ "$code" = 409 ]
check grep -qx "error 409 movie clip is still recording (\`movie stop\` first)" "$WORK/body"
answer=$(post "movie stop")
n=$(sed -n "s|^ok movie stop $out/clip frames=\([0-9]*\)\$|\1|p" <<< "$answer")
[ -n "$n" ] && [ "$n" -ge 3 ] || { stop_wall; fail "movie stop answered '$answer'"; }
check [ "$(ls "$out/clip"/frame-*.png | wc -l)" = "$n" ]
check [ "$(($(wc -l < "$out/clip/frames.csv") - 1))" = "$n" ]
frames 3
check [ "$(ls "$out/clip"/frame-*.png | wc -l)" = "$n" ]
note "$n movie frames, none after the stop"
code=$(curl -s -D "$WORK/headers" -o "$WORK/clip.zip" -w '%{http_code} %{content_type}' "$url/movies/clip")
check [ "$code" = "200 application/zip" ]
check grep -qi '^content-disposition: attachment; filename="clip.zip"' "$WORK/headers"
check python3 - "$WORK/clip.zip" "$out/clip" <<'PY'
import os, sys, zipfile
archive, folder = sys.argv[1:]
with zipfile.ZipFile(archive) as z:
    assert z.testzip() is None, "a damaged member"
    names = sorted(z.namelist())
    want = sorted("clip/" + f for f in os.listdir(folder))
    assert names == want, f"{names} != {want}"
    for name in names:
        with open(os.path.join(folder, os.path.basename(name)), "rb") as f:
            assert z.read(name) == f.read(), name
print(f"the zip holds the movie's {len(names)} files, byte for byte")
PY
refused "movie start clip" "movie start clip: .*/clip already holds a movie"
check [ -z "$(ls "$out/clip"/frame-*.exr 2>/dev/null)" ]
check grep -qx "ok movie start $out/clip-exr" <(post "movie start exr clip-exr")
frames 2
answer=$(post "movie stop")
n=$(sed -n "s|^ok movie stop $out/clip-exr frames=\([0-9]*\)\$|\1|p" <<< "$answer")
[ -n "$n" ] && [ "$n" -ge 2 ] || { stop_wall; fail "movie stop answered '$answer'"; }
check [ "$(ls "$out/clip-exr"/frame-*.exr | wc -l)" = "$n" ]
check [ "$(ls "$out/clip-exr"/frame-*.png | wc -l)" = "$n" ]
note "movie start exr: $n frames as PNG and OpenEXR"
# Its frames deleted, frames.csv left: no movie to download.
rm "$out/clip-exr"/frame-*
code=$(curl -s -o "$WORK/body" -w '%{http_code}' "$url/movies/clip-exr")
echo "GET /movies/clip-exr, frames deleted -> $code $(cat "$WORK/body")"
check [ "$code" = 410 ]

note "a movie whose folder is moved away: its error in GET /status until the stop, which answers it too"
check grep -qx "ok movie start $out/gone" <(post "movie start gone")
mv "$out/gone" "$out/gone-away" # atomic, unlike rm -r racing the next frame's write
for _ in $(seq 300); do curl -s "$url/status" | grep -q '"movie_error"' && break; sleep 0.1; done
curl -s "$url/status"; echo
check grep -q '"movie_error":"frame [0-9]* into '"$out"'/gone: ' <(curl -s "$url/status")
check grep -q '^error movie stop: frame [0-9]* into .*/gone: .*; the movie ended with [0-9]* frames$' <(post "movie stop")
check [ -z "$(curl -s "$url/status" | grep movie_error)" ]
code=$(curl -s -o "$WORK/body" -w '%{http_code}' "$url/movies/gone")
echo "GET /movies/gone -> $code $(cat "$WORK/body")"
check [ "$code" = 410 ]

if [ $mounted = 1 ]; then
    note "a full disk"
    check grep -qx "ok record start $out/full/long.toml" <(post "record start full/long.toml")
    answer=$(post "movie start full/m")
    frames 3
    if [[ "$answer" == "ok movie start"* ]]; then
        check grep -q '"movie_error":"frame [0-9]* into .*/full/m: ' <(curl -s "$url/status")
        check grep -q '^error movie stop: frame .*: ' <(post "movie stop")
        check [ -z "$(curl -s "$url/status" | grep movie_error)" ]
    fi
    [[ "$answer" == "error movie start: frame "* ]] || [[ "$answer" == "ok movie start"* ]] ||
        { stop_wall; fail "movie start on a full disk answered '$answer'"; }
    frames 40 # 8 KiB hold about 30 keys
    check grep -q "^error record stop: .*long.toml" <(post "record stop")
    # The master's stderr reaches the log through mpirun's forwarding, which can lag the answer.
    for _ in $(seq 100); do grep -q 'record: .*long.toml' "$WORK/log" && break; sleep 0.1; done
    check grep -q 'record: .*long.toml' "$WORK/log"
else
    note "SKIP the full-disk part: a tmpfs cannot be mounted here (not root)"
fi

frames 2
check grep -qx 'ok quit' <(post quit)
status=0; wait $job || status=$?
[ $status -eq 0 ] || { cat "$WORK/log"; fail "the wall exited $status"; }
echo "PASS web_record"
