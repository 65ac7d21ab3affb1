#!/bin/bash
# The master's host cut off on the virtual cluster (launch/virtual-cluster, --rank-timeout 3), on 4
# hosts x 1 rank (rank 0 and mpirun alone on host 0) and on 2 hosts x 2 ranks (rank 1 beside them):
# once frames flow, and after a random 0-3 s so the cut falls anywhere in a frame, host 0's link is
# taken down (`ip -n PREFIXh0 link set eth0 down`). The job must end within 15 s of the cut with exit
# status 3, the master's line naming silent ranks on the other hosts (the workers' own lines, which
# name the master, cannot reach mpirun over the cut link), and no process or namespace may be left.
# MASTER_CUT_RUNS=N repeats each layout N times (default 1); MASTER_CUT_LAYOUTS picks layouts
# (default "4x1 2x2"). Everything runs under `timeout`. Skipped (77) where namespaces cannot be made.
source "$(dirname "$0")/lib.sh"
require_network_namespaces
timeout_s=3
limit_s=15
runs_each="${MASTER_CUT_RUNS:-1}"
layouts=(${MASTER_CUT_LAYOUTS:-4x1 2x2}) # HOSTSxRANKS_PER_HOST, 4 ranks in all
runs=$(( runs_each * ${#layouts[@]} ))
base="awmc$(( $$ % 100000 ))" # + the run's number + e0: within the 15 characters of an interface name

# The namespaces of a run the script could not clean up (killed), and their processes.
remove_namespaces() {
    local ns
    for ns in $(ip netns list | awk -v b="$base" 'index($1, b) == 1 { print $1 }'); do
        ip netns pids "$ns" 2>/dev/null | xargs -r kill -KILL 2>/dev/null || true
        ip netns del "$ns" 2>/dev/null || true
    done
}
trap 'remove_namespaces; cleanup' EXIT

failures=0
for run in $(seq "$runs"); do
    layout=${layouts[$(( (run - 1) % ${#layouts[@]} ))]}
    hosts=${layout%x*} per_host=${layout#*x}
    prefix="$base$run"
    log="$WORK/$run.log" err="$WORK/$run.err"
    note "run $run of $runs: $hosts hosts x $per_host ranks, host 0's link down"
    AURORAWALL="$AW" VIRTUAL_CLUSTER_PREFIX="$prefix" timeout -k 5 120 "$SRC_DIR/launch/virtual-cluster" "$hosts" "$per_host" -- \
        render --wall "$WALLS/desktop-2x2.toml" --scene "$SCENE" --frames 1000000 --rank-timeout $timeout_s \
        --verbose --out "$WORK/out$run" > "$log" 2> "$err" &
    job=$!
    for _ in $(seq 900); do
        grep -q "^frame 3 " "$log" && break
        kill -0 $job 2>/dev/null || { cat "$log" "$err"; fail "run $run: the job ended before frame 3"; }
        sleep 0.1
    done
    grep -q "^frame 3 " "$log" || { kill $job; fail "run $run: no frame 3 in 90 s"; }
    pids=$(sed -n 's/^rank [0-3]: pid \([0-9]*\)$/\1/p' "$log")
    [ "$(wc -w <<<"$pids")" -eq 4 ] || fail "run $run: not every rank printed its pid"

    sleep "$(awk -v r=$RANDOM 'BEGIN { print r % 3000 / 1000 }')"
    ip -n "${prefix}h0" link set eth0 down
    cut=$(now)
    for _ in $(seq $(( limit_s * 10 ))); do kill -0 $job 2>/dev/null || break; sleep 0.1; done
    problems=()
    if kill -0 $job 2>/dev/null; then
        problems+=("still running $limit_s s after the cut")
        kill $job 2>/dev/null || true # timeout passes it on: the script removes its namespaces
    fi
    status=0; wait $job || status=$?
    took=$(elapsed "$cut")
    note "run $run: exit status $status, $took s after the cut"
    cat "$err" >&2
    [ "$status" -eq 3 ] || problems+=("exit status $status, expected 3")
    # The master names the ranks whose silence passed the timeout at the moment it looked: at least
    # one, each with its host (another host than the master's).
    line=$(grep "^aurorawall render: no heartbeat for more than --rank-timeout $timeout_s s from rank" "$err" || true)
    [ -n "$line" ] || problems+=("no line of the master naming a silent rank")
    for r in $(grep -o "rank [0-9]* on ${prefix}h[0-9]* (last heard" <<<"$line" | awk '{ print $2 }'); do
        [ "$r" -ge "$per_host" ] && grep -q "rank $r on ${prefix}h$(( r / per_host )) (last heard" <<<"$line" ||
            problems+=("the master's line names rank $r wrongly")
    done
    for pid in $pids; do
        for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
        kill -0 "$pid" 2>/dev/null && { problems+=("rank pid $pid left behind"); kill -KILL "$pid"; }
    done
    [ -z "$(ip netns list | grep "$prefix")" ] || problems+=("namespaces left behind")
    [ -z "$(pgrep -f "$prefix" || true)" ] || problems+=("processes left behind")
    remove_namespaces
    if [ ${#problems[@]} -gt 0 ]; then
        for problem in "${problems[@]}"; do echo "FAIL run $run: $problem" >&2; done
        failures=$(( failures + 1 ))
    fi
done
note "$(( runs - failures )) of $runs runs ended correctly"
[ "$failures" -eq 0 ] || fail "$failures of $runs runs"
echo "PASS virtual cluster master cut"
