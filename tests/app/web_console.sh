#!/bin/bash
# The browser console: a 2-rank headless wall with --web-port 0 --frames 0 and a token file serves
# the page, a PNG preview that changes while the wall plays, /status as JSON and POST /command with
# the control port's commands (pause, time, preset, screenshot, the screenshot then served at GET
# /screenshots/NAME); a malformed request, a huge body,
# a path leaving the page's folder, a missing or wrong secret, 100 requests at once and a client that
# never reads are refused or served and the wall keeps drawing; POST quit ends the job with 0.
source "$(dirname "$0")/lib.sh"
command -v curl >/dev/null || { echo "SKIP: curl is not installed"; exit 77; }

make_token
start_web_wall "$WORK" --control-token-file "$WORK/token"
check() { "$@" || { stop_wall; fail "$*"; }; }

# get PATH [CURL ARGS...]: the status code, the body in $WORK/body.
get() { local path="$1"; shift; curl -s -o "$WORK/body" -w '%{http_code}' -H "Authorization: Bearer $secret" "$@" "$url$path"; }
# post LINE: the command's answer line; fails unless 200.
post() {
    local code
    code=$(curl -s -o "$WORK/body" -w '%{http_code}' -H "Authorization: Bearer $secret" --data-binary "$1" "$url/command")
    [ "$code" = 200 ] || { stop_wall; fail "POST '$1' -> $code $(cat "$WORK/body")"; }
    echo "$1 -> $(cat "$WORK/body")" >&2
    cat "$WORK/body"
}
# status NAME: a member of /status.
status() {
    check [ "$(get /status)" = 200 ]
    python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])' "$WORK/body" "$1"
}

# The page, its script and style, without the secret (they are the repository's files).
check [ "$(curl -s -o "$WORK/page" -w '%{http_code}' "$url/")" = 200 ]
check grep -q '<title>aurorawall console</title>' "$WORK/page"
check [ "$(curl -s -o /dev/null -w '%{http_code}' "$url/console.js")" = 200 ]
check [ "$(curl -s -o /dev/null -w '%{http_code}' "$url/console.css")" = 200 ]
check [ "$(get /presets)" = 200 ]
check grep -q '"ground-65n"' "$WORK/body"
# Each rank's last frame (2 ranks): the frame it drew, its times, and the age of its last heartbeat
# at the master (a beat every 1 s at the default --rank-timeout 10: allowed up to 5 s on a loaded machine).
for _ in $(seq 100); do [ "$(get /ranks)" = 200 ] && grep -q '"render_ms"' "$WORK/body" && break; sleep 0.1; done
check python3 - "$WORK/body" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
print("GET /ranks ->", r)
assert len(r["ranks"]) == 2 and all(k["frame"] == r["frame"] and k["render_ms"] > 0 for k in r["ranks"]), r
assert r["heartbeat_period_s"] == 1, r
ages = [k["heartbeat_age_s"] for k in r["ranks"]]
assert all(isinstance(a, (int, float)) and 0 <= a < 5 for a in ages), ages
assert ages[0] == 0, ages  # the master hears the others
PY

# The preview: a PNG (503 until the first wall is gathered), a new one once a frame shows a new
# camera. (The test scene's curtains drift, but on this 64x36 wall not by a whole 8-bit step: its
# screenshots are the same bytes at 0 and 5000 s, so the camera makes the change.)
preview() {
    for _ in $(seq 100); do
        [ "$(get /preview.png)" = 200 ] && break
        sleep 0.1
    done
    check [ "$(head -c 8 "$WORK/body" | od -An -tx1 | tr -d ' ')" = 89504e470d0a1a0a ]
    cp "$WORK/body" "$1"
}
preview "$WORK/p1.png"
frame1=$(status frame)
check grep -qx 'ok goto lat_deg=65 lon_deg=25 alt_km=200' <(post "goto 65 25 200")
for _ in $(seq 50); do
    preview "$WORK/p2.png"
    cmp -s "$WORK/p1.png" "$WORK/p2.png" || break
    sleep 0.1
done
frame2=$(status frame)
cmp -s "$WORK/p1.png" "$WORK/p2.png" && { stop_wall; fail "the preview did not change from frame $frame1 to $frame2"; }
note "preview changed between frames $frame1 and $frame2"

# The control port's commands, answered the same.
check grep -q '^ok paused at time_s=' <(post pause)
check grep -qx 'ok time_s=120' <(post "time 120")
check [ "$(status time_s)" = 120 ]
check [ "$(status paused)" = True ]
check grep -qx 'ok preset ground-65n lat_deg=65.000000 lon_deg=20.000000 alt_km=0.300000' <(post "preset ground-65n")
check [ "$(status lat_deg)" = 65.0 ]
check [ "$(status lon_deg)" = 20.0 ]
check [ "$(status alt_km)" = 0.3 ]
check grep -q "^error unknown command 'xyzzy'" <(post "xyzzy 1")
check grep -q "^error screenshot \.\./x\.png: '\.\.' would leave the output folder" <(post "screenshot ../x.png")
check grep -q '^ok screenshot .*/web\.png$' <(post "screenshot web.png")
check [ -s "$WORK/web.png" ]
# The screenshot for download: the same bytes, with the secret only; no other file.
check [ "$(get /screenshots/web.png -D "$WORK/headers")" = 200 ]
check cmp "$WORK/body" "$WORK/web.png"
check grep -qi '^content-type: image/png' "$WORK/headers"
check [ "$(curl -s -o /dev/null -w '%{http_code}' "$url/screenshots/web.png")" = 401 ]
check [ "$(get /screenshots/other.png)" = 404 ]

# Bad requests: one clear refusal each, and the wall goes on.
check [ "$(curl -s -o /dev/null -D "$WORK/headers" -w '%{http_code}' "$url/status")" = 401 ]
check grep -qi '^www-authenticate: Bearer' "$WORK/headers"
check [ "$(curl -s -o /dev/null -w '%{http_code}' -H 'Authorization: Bearer wrong' -d quit "$url/command")" = 401 ]
check [ "$(curl -s -o /dev/null -w '%{http_code}' -H 'Authorization: Bearer wrong' "$url/preview.png")" = 401 ]
check [ "$(get /command --data-binary @<(head -c 100000 /dev/zero | tr '\0' a))" = 413 ]
check grep -q '^error 413 request too large' "$WORK/body"
check [ "$(get /command --data-binary $'status\nquit')" = 400 ]
# The limit is of the line: 1024 bytes with its newline are taken (an unknown word, answered), 1025 are not.
long=$(head -c 1024 /dev/zero | tr '\0' a)
check [ "$(get /command --data-binary "$long"$'\r\n')" = 200 ]
check grep -q "^error unknown command" "$WORK/body"
check [ "$(get /command --data-binary "${long}a")" = 413 ]
# A chunked body (which would be read whole, past the limit) and a route asked with the wrong method.
check [ "$(get /command -H 'Transfer-Encoding: chunked' --data-binary @<(head -c 100000 /dev/zero | tr '\0' a))" = 411 ]
check grep -q '^error 411 length required' "$WORK/body"
check [ "$(get /command -D "$WORK/headers")" = 405 ]
check grep -qi '^allow: POST' "$WORK/headers"
check [ "$(get /status -d x)" = 405 ]
check grep -q '^error 405 method not allowed (/status takes GET)' "$WORK/body"
# A second wall on this wall's port: refused, naming the option (it would have shared the port).
"$SRC_DIR/launch/one-screen-wall" 32x18 >"$WORK/tiny-1x1.toml"
code=0
timeout 60 "$AW" render --wall "$WORK/tiny-1x1.toml" --scene "$SCENE" --frames 0 --web-port "$port" \
    >"$WORK/second.log" 2>&1 || code=$?
check [ "$code" = 1 ]
check grep -q -- "--web-port $port: cannot listen" "$WORK/second.log"
for path in /../../etc/passwd /%2e%2e/%2e%2e/etc/passwd /..%2f..%2fetc/passwd /nothing.html; do
    code=$(get "$path" --path-as-is)
    [ "$code" = 404 ] || [ "$code" = 400 ] || { stop_wall; fail "GET $path -> $code $(head -c 200 "$WORK/body")"; }
    check grep -q '^error 40' "$WORK/body"
    echo "GET $path -> $code $(cat "$WORK/body")"
done
python3 - "$port" "$secret" <<'PY' || { stop_wall; fail "the bad clients"; }
import socket, sys, threading, urllib.request
port, secret = int(sys.argv[1]), sys.argv[2]

def raw(data):
    s = socket.create_connection(("127.0.0.1", port), timeout=10)
    s.sendall(data)
    answer = s.recv(4096).decode(errors="replace")
    s.close()
    return answer.split("\r\n")[0]

line = raw(b"GARBAGE\r\n\r\n")
print("malformed request line ->", line)
assert line.startswith("HTTP/1.1 400"), line
auth = b"Authorization: Bearer %s\r\n" % secret.encode()
for request in (b"GET /console.js%00.html HTTP/1.1\r\nHost: x\r\n\r\n",
                b"POST /command HTTP/1.1\r\nHost: x\r\n" + auth + b"Content-Length: abc\r\n\r\nstatus",
                b"POST /command HTTP/1.1\r\nHost: x\r\n" + auth + b"Content-Length: 6\r\nContent-Length: 4\r\n\r\nstatus"):
    line = raw(request)
    print(request.split(b"\r\n")[0], "... ->", line)
    assert line.startswith("HTTP/1.1 400"), line

# A client that sends requests and never reads the answers: the server gives up on it (write timeout).
stuck = socket.create_connection(("127.0.0.1", port))
stuck.sendall(b"".join(b"GET /preview.png HTTP/1.1\r\nHost: x\r\nAuthorization: Bearer %s\r\n\r\n" % secret.encode()
                       for _ in range(200)))

codes = []
def ask():
    request = urllib.request.Request(f"http://127.0.0.1:{port}/status", headers={"Authorization": "Bearer " + secret})
    try:
        with urllib.request.urlopen(request, timeout=60) as r:
            codes.append(r.status)
    except Exception as e:
        codes.append(str(e))
threads = [threading.Thread(target=ask) for _ in range(100)]
for t in threads: t.start()
for t in threads: t.join()
stuck.close()
print("100 requests at once ->", {c: codes.count(c) for c in set(codes)})
assert codes == [200] * 100
PY
frame3=$(status frame)
sleep 1
check [ "$(status frame)" -gt "$frame3" ]
note "the wall still draws (frame $frame3 and on)"

# The page in a real browser (headless Chromium), its script run for 3 s of virtual time with the
# secret in the address: the status line filled from /status, a button for each preset from
# /presets, the preview shown from /preview.png, and no alarm.
check command -v chromium # launch/install-deps installs it
chromium --headless --no-sandbox --disable-gpu --virtual-time-budget=3000 --dump-dom "$url/#token=$secret" \
    2>/dev/null > "$WORK/dom.html" || true
check grep -Eq '<p id="status" class="status">frame [0-9]+  t=120\.0 s .* paused ' "$WORK/dom.html"
check grep -q '<button type="button">ground-65n</button>' "$WORK/dom.html"
check grep -Eq '<img id="preview" [^>]*src="blob:' "$WORK/dom.html"
check grep -q '<p id="alarm" class="alarm" hidden' "$WORK/dom.html"
check [ "$(grep -o 'rank [0-9]: [0-9.]* ms, waited' "$WORK/dom.html" | wc -l)" -eq 2 ]
check grep -Eq 'rank 1: [0-9.]+ ms, waited [0-9.]+ ms, heard [0-9.]+ s ago' "$WORK/dom.html"
note "the page's script ran in Chromium: $(grep -o '<p id="status" class="status">[^<]*' "$WORK/dom.html" | sed 's/.*>//')"

check grep -qx 'ok quit' <(post quit)
for _ in $(seq 300); do kill -0 $job 2>/dev/null || break; sleep 0.1; done
kill -0 $job 2>/dev/null && { stop_wall; fail "still running 30 s after quit"; }
code=0; wait $job || code=$?
cat "$WORK/log"
[ $code -eq 0 ] || fail "the job exited $code after quit"
echo "PASS web_console"
