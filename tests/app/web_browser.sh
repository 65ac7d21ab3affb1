#!/bin/bash
# The browser console's buttons pressed in headless Chromium (web_browser.py, over the DevTools
# protocol): on a 2-rank headless wall with --web-port 0 --frames 0 and a token file, the page asks
# for the secret and refuses a wrong one, pause, the time slider, play and a preset change what GET
# /status reports, the preview on the page changes with the camera, the screenshot and the recorded
# path are downloaded, rank 1 stopped for a few seconds is drawn red with its heartbeat's age, and a
# screenshot of the page is taken (WEB_BROWSER_SCREENSHOT=FILE keeps a copy); then POST
# quit ends the job with 0.
source "$(dirname "$0")/lib.sh"
[ -x /usr/bin/chromium ] || { echo "SKIP: /usr/bin/chromium is not installed"; exit 77; }
command -v curl >/dev/null || { echo "SKIP: curl is not installed"; exit 77; }

make_token
start_web_wall "$WORK" --control-token-file "$WORK/token"

# Rank 1's process: the child of mpirun (the child of the job's subshell) whose MPI rank is 1.
rank1=""
for pid in $(pgrep -P "$(pgrep -P "$job" | head -1)"); do
    grep -qz '^OMPI_COMM_WORLD_RANK=1$' "/proc/$pid/environ" 2>/dev/null && rank1=$pid
done
[ -n "$rank1" ] || { stop_wall; fail "rank 1's process not found"; }

# The scene's camera is at 65 N 15 E, 0.5 km; the preset ground-65n's at 65 N 20 E, 0.3 km.
# The tiny wall's canvas: 2x2 screens of 32x18 px without bezels.
python3 "$HERE/web_browser.py" "$url" "$secret" "$WORK" ground-65n "$rank1" 64x36 || {
    stop_wall; tail -20 "$WORK/chromium.log" >&2; fail "the page's buttons in Chromium"; }
[ -n "${WEB_BROWSER_SCREENSHOT:-}" ] && cp "$WORK/console.png" "$WEB_BROWSER_SCREENSHOT"

answer=$(curl -s -H "Authorization: Bearer $secret" --data-binary quit "$url/command")
[ "$answer" = "ok quit" ] || { stop_wall; fail "POST quit -> $answer"; }
for _ in $(seq 300); do kill -0 $job 2>/dev/null || break; sleep 0.1; done
kill -0 $job 2>/dev/null && { stop_wall; fail "still running 30 s after quit"; }
code=0; wait $job || code=$?
[ $code -eq 0 ] || { cat "$WORK/log"; fail "the job exited $code after quit"; }
echo "PASS web_browser"
