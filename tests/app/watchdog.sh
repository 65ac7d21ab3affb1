#!/bin/bash
# Never hang: a rank stopped with SIGSTOP is named by the master within --rank-timeout (+ 5 s) and the
# job exits 3; a stopped master is named by the workers likewise; a rank whose main thread hangs while its heartbeat thread runs (the test hook
# AURORAWALL_TEST_HANG_MAIN_THREAD) likewise; a rank killed with SIGKILL ends the job (through Open
# MPI) within a few seconds; a 4-rank wall on 2 cores at --rank-timeout 2 raises no false alarm.
# Movies: 3 frames give 3 PNGs, 3 EXRs and frames.csv with each frame's exact time, and the last
# frame equals wall.png.
source "$(dirname "$0")/lib.sh"
wall3="$WALLS/desktop-3x1.toml"
timeout_s=3

# start_long_run NAME: a 3-rank headless run that would last for hours, in the background (job=$!).
start_long_run() {
    aw_mpirun 3 render --wall "$wall3" --scene "$SCENE" --frames 1000000 --rank-timeout $timeout_s \
        --verbose --out "$WORK/$1" > "$WORK/$1.log" 2> "$WORK/$1.err" &
    job=$!
}

# rank_pid NAME RANK: the pid rank RANK printed in verbose mode (waits for it).
rank_pid() {
    local pid=""
    for _ in $(seq 600); do
        pid=$(sed -n "s/^rank $2: pid \([0-9]*\)$/\1/p" "$WORK/$1.log")
        [ -n "$pid" ] && grep -q "^frame" "$WORK/$1.log" && break
        kill -0 $job 2>/dev/null || { cat "$WORK/$1.log" "$WORK/$1.err"; fail "$1: the job ended early"; }
        sleep 0.1
    done
    [ -n "$pid" ] || fail "$1: rank $2 printed no pid"
    echo "$pid"
}

# wait_end NAME LIMIT_S [EVENT]: waits for the job to end, at most LIMIT_S seconds; sets status and took.
wait_end() {
    local start; start=$(now)
    for _ in $(seq $(( $2 * 10 ))); do kill -0 $job 2>/dev/null || break; sleep 0.1; done
    if kill -0 $job 2>/dev/null; then
        kill -KILL $victim 2>/dev/null || true; kill $job; fail "$1: still running $2 s later"
    fi
    status=0; wait $job || status=$?
    took=$(elapsed "$start")
    note "$1: the job exited $status ${took} s after ${3:-the signal}"
}

# wait_frame NAME FRAME: waits until the master has printed FRAME's line.
wait_frame() {
    for _ in $(seq 600); do
        grep -q "^frame $2 " "$WORK/$1.log" && return
        kill -0 $job 2>/dev/null || { cat "$WORK/$1.log" "$WORK/$1.err"; fail "$1: the job ended early"; }
        sleep 0.1
    done
    fail "$1: no frame $2"
}

# stop_case NAME RANK EXPECTED: SIGSTOP rank RANK of a long run; the job must end with status 3 within
# --rank-timeout + 5 s, its stderr must say EXPECTED, and the stopped process must be gone.
stop_case() {
    start_long_run "$1"
    victim=$(rank_pid "$1" "$2")
    kill -STOP "$victim"
    wait_end "$1" $(( timeout_s + 5 ))
    cat "$WORK/$1.err" >&2
    [ "$status" -eq 3 ] || fail "$1: exit status $status, expected 3"
    grep -q "$3" "$WORK/$1.err" || fail "$1: stderr does not say '$3'"
    expect_gone "$victim" "$1: the stopped process"
    return 0
}

note "SIGSTOP rank 2 at --rank-timeout $timeout_s"
stop_case stop 2 "no heartbeat for more than --rank-timeout $timeout_s s from rank 2 on [^ ]* (last heard: "
grep -q "rank 1 on " "$WORK/stop.err" && fail "stop: rank 1 was named too"

note "SIGSTOP the master (rank 0) at --rank-timeout $timeout_s"
stop_case stopmaster 0 "no heartbeat for more than --rank-timeout $timeout_s s from the master (rank 0 on "

note "rank 2's main thread hangs drawing frame 3, --rank-timeout $timeout_s"
AURORAWALL_TEST_HANG_MAIN_THREAD=2:3 start_long_run hang
victim=$(rank_pid hang 2)
wait_frame hang 2 # the gather of frame 2 is printed just before every rank starts frame 3
wait_end hang $(( timeout_s + 5 )) "the hang"
cat "$WORK/hang.err" >&2
[ "$status" -eq 3 ] || fail "hang: exit status $status, expected 3"
grep -q "hung: rank 2 on [^ ]* (drawing frame 3, its main thread without progress for " "$WORK/hang.err" ||
    fail "hang: stderr does not name rank 2 drawing frame 3"
grep -q "rank 1 on " "$WORK/hang.err" && fail "hang: rank 1 was named too"
grep -q "no heartbeat" "$WORK/hang.err" && fail "hang: taken for a silent rank"
expect_gone "$victim" "hang: the hung rank's process"

note "SIGKILL rank 1"
start_long_run kill
victim=$(rank_pid kill 1)
kill -KILL "$victim"
wait_end kill 10
[ "$status" -ne 0 ] || fail "kill: exit status 0"

note "4 ranks on 2 cores, --rank-timeout 2: no false alarm"
aw_mpirun 4 render --wall "$DATA/tiny-2x2.toml" --scene "$SCENE" --frames 40 --rank-timeout 2 --quiet \
    --out "$WORK/slow" > "$WORK/slow.log" 2>&1 || { cat "$WORK/slow.log"; fail "slow: the run failed"; }
grep -q "heartbeat\|hung" "$WORK/slow.log" && fail "slow: a false alarm"

note "movie: 3 frames"
# The test scene's curtains drift along themselves, so the camera flies (20 km/s) to make frames differ.
sed 's/^speed_km_per_s = 0.0$/speed_km_per_s = 20.0/' "$SCENE" > "$WORK/flying.toml"
aw_mpirun 3 render --wall "$wall3" --scene "$WORK/flying.toml" --frames 3 --start-time 5 --dt 0.7 --gather \
    --movie "$WORK/movie" --movie-exr --quiet --out "$WORK/movie-out" > "$WORK/movie.log" 2>&1 ||
    { cat "$WORK/movie.log"; fail "movie: the run failed"; }
for f in 0 1 2; do
    for ext in png exr; do
        [ -s "$WORK/movie/frame-00000$f.$ext" ] || fail "movie: frame-00000$f.$ext is missing"
    done
done
[ "$(find "$WORK/movie" -type f | wc -l)" -eq 7 ] || { ls -a "$WORK/movie"; fail "movie: not 7 files"; }
# The master clock's time of frame n is 5 + n x 0.7 in double, written with 17 digits.
expected=$(awk 'BEGIN { print "frame,time_s"; for (n = 0; n < 3; ++n) printf "%d,%.17g\n", n, 5 + n * 0.7 }')
[ "$(cat "$WORK/movie/frames.csv")" = "$expected" ] ||
    { cat "$WORK/movie/frames.csv"; fail "movie: frames.csv is not the expected 3 rows"; }
cmp "$WORK/movie/frame-000002.png" "$WORK/movie-out/wall.png" || fail "movie: the last frame differs from wall.png"
cmp -s "$WORK/movie/frame-000000.png" "$WORK/movie/frame-000002.png" && fail "movie: the frames do not move"
echo "PASS watchdog"
