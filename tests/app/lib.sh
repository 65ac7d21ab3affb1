# Shared by the end-to-end driver scripts of tests/app (sourced, not run).
# The test registration (CMakeLists.txt) sets:
#   AW          the aurorawall binary           MPIEXEC   mpirun
#   COMPARE     the compare_walls binary        SRC_DIR   the source tree
#   DATA        tests/app/data                  HERE      tests/app
#   AW_TIME_SCALE  how many times longer the time limits are (10 under the sanitizers)
set -euo pipefail

: "${AW:?}" "${MPIEXEC:?}" "${SRC_DIR:?}" "${DATA:?}" "${HERE:?}"
WALLS="$SRC_DIR/config/walls"
SCENE="$DATA/overhead.toml" # the fast test scene with curtains across every tile

# Open MPI as root in a container, quick shared-memory start-up, more ranks than cores.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
MPI_FLAGS=(--oversubscribe --bind-to none --mca pml ob1 --mca btl self,vader)

WORK="$(mktemp -d "${TMPDIR:-/tmp}/aw-e2e.XXXXXX")"
cleanup() { rm -rf "$WORK"; }
trap cleanup EXIT

# The remote-control client (launch/wall-control), waiting 30 s for an answer, AW_TIME_SCALE times
# longer under the sanitizers.
client=(python3 "$SRC_DIR/launch/wall-control" --timeout $((30 * ${AW_TIME_SCALE:-1})))

fail() { echo "FAIL: $*" >&2; exit 1; }
note() { echo "== $*"; }

# aw_mpirun N ARGS...: mpirun -n N aurorawall ARGS. Several ranks on 2 cores run faster with one
# llvmpipe thread each; a single rank keeps llvmpipe's default.
aw_mpirun() {
    local n="$1"; shift
    local threads=()
    if [ "$n" -gt 1 ]; then threads=(-x LP_NUM_THREADS=1); fi
    "$MPIEXEC" -n "$n" "${MPI_FLAGS[@]}" "${threads[@]}" "$AW" "$@"
}

# expect_gone PID WHAT: the process PID ends within 5 s; otherwise it is killed and the test fails
# with "WHAT is left behind".
expect_gone() {
    local pid="$1" what="$2"
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || return 0; sleep 0.1; done
    kill -KILL "$pid" 2>/dev/null
    fail "$what is left behind"
}

# Seconds since the epoch with nanoseconds, for timing.
now() { date +%s.%N; }
elapsed() { awk -v a="$(now)" -v b="$1" 'BEGIN { printf "%.2f", a - b }'; }

# control_port LOG JOB: waits (at most 60 s) until the wall started in the background as JOB writes
# "control: listening on 127.0.0.1:PORT" to LOG, and prints PORT; fails (killing JOB) otherwise.
# Use as port=$(control_port LOG JOB): a failure exits the script under set -e.
# web_port LOG JOB: the same for --web-port's "web: listening on 127.0.0.1:PORT".
control_port() { listening_port control "$@"; }
web_port() { listening_port web "$@"; }

# start_web_wall OUT [RENDER ARGS...]: a 2-rank headless wall of tiny screens (two per rank) on $SCENE
# serving the browser console on a free port (--frames 0 --web-port 0 --quiet --out OUT, the log in
# $WORK/log), in the background; sets job (the aw_mpirun subshell), port and url.
start_web_wall() {
    local out="$1" wall="$WORK/tiny-2-ranks.toml"
    shift
    { cat "$DATA/tiny-2x2.toml"; printf '\n[ranks]\nscreens_per_rank = 2\n'; } > "$wall"
    aw_mpirun 2 render --wall "$wall" --scene "$SCENE" --frames 0 --web-port 0 --quiet --out "$out" "$@" \
        > "$WORK/log" 2>&1 &
    job=$!
    port=$(web_port "$WORK/log" "$job")
    url="http://127.0.0.1:$port"
    note "console on $url"
}
# Ends a start_web_wall job on a failure: mpirun, started by the aw_mpirun subshell $job, and the subshell.
stop_wall() { pkill -P "$job" 2>/dev/null; kill "$job" 2>/dev/null; }
# A secret for --control-token-file: $secret, written to $WORK/token (owner only).
make_token() {
    secret="s3cret-$$"
    echo "$secret" > "$WORK/token"
    chmod 600 "$WORK/token"
}
listening_port() {
    local what="$1" log="$2" job="$3" port
    for _ in $(seq 600); do
        grep -q "^$what: listening on" "$log" && break
        kill -0 "$job" 2>/dev/null || { cat "$log" >&2; fail "the wall exited before listening"; }
        sleep 0.1
    done
    port=$(sed -n "s/^$what: listening on 127\.0\.0\.1:\([0-9]*\)\$/\1/p" "$log")
    [ -n "$port" ] || { cat "$log" >&2; kill "$job"; fail "no '$what: listening on 127.0.0.1:PORT' line"; }
    echo "$port"
}

# Xvfb options for every window test. -noreset: Xvfb otherwise resets whenever its last client
# leaves, and a client connecting during the reset fails with "Failed to open display" (a window
# counter polling with xwininfo while ranks start: 5 of 1200 connections failed on 2 loaded cores
# without it, 0 of 1200 with it).
XVFB_OPTIONS="-noreset"

# For the scripts that type into GLFW windows: unless the script was called with --inside-x, runs it
# again (exec) inside a new Xvfb whose first screen is SCREEN ("WxHxDEPTH"), with --inside-x;
# exits 77 (skipped) without xvfb-run or xdotool. Usage: run_under_xvfb SCREEN "$@".
run_under_xvfb() {
    local screen="$1"; shift
    [ "${1:-}" = --inside-x ] && return 0
    if [ -z "${XVFB_RUN:-}" ] || ! [ -x "$XVFB_RUN" ]; then echo "SKIP: xvfb-run is not installed"; exit 77; fi
    if ! command -v xdotool >/dev/null; then echo "SKIP: xdotool is not installed"; exit 77; fi
    exec "$XVFB_RUN" -a -s "-screen 0 $screen $XVFB_OPTIONS" bash "$0" --inside-x
}

# For the scripts that steer a wall over its control port (they define `ask`, which sends one command
# and fails unless answered ok): a field of a `status` answer, and the wall's status once the field
# NAME differs from its value in the earlier answer BEFORE (polled for up to 20 s), plus one second
# for the rest of the input to arrive. Usage: field NAME ANSWER; status_once_changed NAME BEFORE.
field() { sed -n "s/.* $1=\([^ ]*\).*/\1/p" <<<"$2"; }
status_once_changed() {
    local name="$1" before="$2"
    for _ in $(seq 200); do
        [ "$(field "$name" "$(ask status)")" != "$(field "$name" "$before")" ] && break
        sleep 0.1
    done
    sleep 1
    ask status
}

# For the scripts on launch/virtual-cluster: exits 77 (skipped) where network namespaces cannot be
# made (not root, or no ip netns).
require_network_namespaces() {
    local probe="awprobe$$"
    if ! ip netns add "$probe" 2>/dev/null; then
        echo "SKIPPED: network namespaces cannot be made here (needs root and ip netns)"
        exit 77
    fi
    ip netns del "$probe"
}
