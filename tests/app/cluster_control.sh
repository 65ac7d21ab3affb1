#!/bin/bash
# The control port on a lab network, on the virtual cluster (launch/virtual-cluster, 2 hosts x 2
# ranks): the master listens on host 0's address with --control-token-file; a client on host 1 that
# does not authenticate gets one error line and is closed, and the wall keeps running; one that
# sends the secret first steers the wall (status, pause, quit) and the job exits 0. A flood of
# 10,000 lines per second from host 1 (launch/control-flood, connecting again whenever closed): with
# the secret, each connection has at most 100 lines answered, then the one rate error, and is closed,
# while the wall keeps drawing and answering, also for a flood of one screenshot (the file written,
# at most one screenshot frame every 0.5 s, the other lines refused with why); without it, each connection gets nothing but the one authentication error. No timing is checked (launch/control-flood-bench measures the frame time).
# Skipped (77) where namespaces cannot be made.
source "$(dirname "$0")/lib.sh"
require_network_namespaces
prefix="awcc$$"
token="$WORK/token"
echo "secret-$$-$RANDOM" > "$token"
chmod 600 "$token"
AURORAWALL="$AW" VIRTUAL_CLUSTER_PREFIX="$prefix" "$SRC_DIR/launch/virtual-cluster" 2 2 -- render \
    --wall "$DATA/tiny-2x2.toml" --scene "$SCENE" --frames 0 --control-port 5555 --control-bind 198.18.0.1 \
    --control-token-file "$token" --out "$WORK/out" > "$WORK/log" 2> "$WORK/err" &
job=$!
for _ in $(seq 600); do
    grep -q "^control: listening on 198.18.0.1:5555" "$WORK/log" && grep -q "^frame" "$WORK/log" && break
    kill -0 $job 2>/dev/null || { cat "$WORK/log" "$WORK/err"; fail "the job ended early"; }
    sleep 0.1
done
grep -q "^control: listening on 198.18.0.1:5555" "$WORK/log" || { kill $job; fail "no control port"; }
from_host1() { ip netns exec "${prefix}h1" python3 "$SRC_DIR/launch/wall-control" --host 198.18.0.1 --port 5555 "$@"; }

note "a client on host 1 without the secret"
code=0; answer=$(from_host1 status pause 2>&1) || code=$?
echo "$answer"
[ $code -eq 1 ] || { kill $job; fail "unauthenticated client: exit $code, expected 1"; }
[ "$(head -n 1 <<<"$answer")" = "error authentication required: the first line must be auth TOKEN; closing" ] ||
    { kill $job; fail "unauthenticated client: '$answer'"; }
# The second line finds the connection closed (wall-control says so: closed, or reset).
[ "$(grep -c '^wall-control: ' <<<"$answer")" = 1 ] && [ "$(grep -vc '^wall-control: ' <<<"$answer")" = 1 ] ||
    { kill $job; fail "unauthenticated client: not closed after its first line"; }

note "a client on host 1 with the secret"
answer=$(from_host1 --token-file "$token" status pause status) || { kill $job; fail "authenticated client: '$answer'"; }
echo "$answer"
[ "$(head -n 1 <<<"$answer")" = "ok auth" ] || { kill $job; fail "no ok auth"; }
grep -q " paused " <<<"$answer" || { kill $job; fail "the wall was not paused"; }
frame_from_host1() { from_host1 --token-file "$token" status | sed -n 's/^ok frame=\([0-9]*\) .*/\1/p'; }
# check_flood JSON PYTHON_CONDITION MESSAGE: fails (killing the job) unless the condition holds for
# the flood's report r.
check_flood() {
    python3 -c "import json, sys; r = json.loads(sys.argv[1]); sys.exit(0 if ($2) else 1)" "$1" ||
        { kill $job; fail "$3: $1"; }
}
flood() { ip netns exec "${prefix}h1" python3 "$SRC_DIR/launch/control-flood" --host 198.18.0.1 --port 5555 "$@"; }

note "a flood of 10,000 lines per second from host 1, with the secret, for 4 s"
before=$(frame_from_host1)
report=$(flood --token-file "$token" --rate 10000 --seconds 4)
after=$(frame_from_host1)
echo "$report; frames $before -> $after"
rate_error="error more than 100 lines per second; closing"
check_flood "$report" "r['sent'] > 1000" "the flood did not get going"
check_flood "$report" "list(r['errors']) == ['$rate_error'] and r['closed_by_wall'] >= 1" "not limited"
# One error line for each connection the wall closed; the last connection may have had its error line
# but not yet its close when the flood ended.
check_flood "$report" "r['closed_by_wall'] <= r['errors']['$rate_error'] <= r['closed_by_wall'] + 1 and r['most_errors_in_a_connection'] == 1" \
    "not one error line for each connection closed"
check_flood "$report" "0 < r['ok'] <= 100 * r['connections']" "more than 100 lines answered on a connection"
[ -n "$after" ] && [ "$after" -gt "$before" ] || { kill $job; fail "the wall stopped drawing ($before -> $after)"; }

note "a flood of one screenshot, with the secret, for 2 s: the file written, at most 2 screenshot frames a second"
report=$(flood --token-file "$token" --rate 10000 --seconds 2 --line "screenshot flood.png")
echo "$report"
too_soon="error screenshot flood.png: the last was taken less than 0.5 s ago (at most 2 a second; --movie records every frame)"
check_flood "$report" "r['ok'] >= 1 and set(r['errors']) <= {'$rate_error', '$too_soon'} and r['errors'].get('$too_soon', 0) > 0" \
    "screenshots not limited to 2 frames a second"
[ "$(head -c 8 "$WORK/out/flood.png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || { kill $job; fail "no flood.png"; }

note "the same flood without the secret, for 2 s"
report=$(flood --rate 10000 --seconds 2)
echo "$report"
auth_error="error authentication required: the first line must be auth TOKEN; closing"
check_flood "$report" "r['ok'] == 0 and list(r['errors']) == ['$auth_error']" "an unauthenticated flood got more than the error"
check_flood "$report" "1 <= r['closed_by_wall'] <= r['errors']['$auth_error'] <= r['closed_by_wall'] + 1 and r['most_errors_in_a_connection'] == 1" \
    "not one error line for each connection closed"

from_host1 --token-file "$token" quit || { kill $job; fail "quit refused"; }
status=0; wait $job || status=$?
[ "$status" -eq 0 ] || { cat "$WORK/err"; fail "the job exited $status after quit"; }
[ -z "$(ip netns list | grep "$prefix")" ] || fail "namespaces left behind"
echo "PASS cluster control"
