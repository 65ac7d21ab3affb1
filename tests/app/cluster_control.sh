#!/bin/bash
# The control port on a lab network, on the virtual cluster (launch/virtual-cluster, 2 hosts x 2
# ranks): the master listens on host 0's address with --control-token-file; a client on host 1 that
# does not authenticate gets one error line and is closed, and the wall keeps running; one that
# sends the secret first steers the wall (status, pause, quit) and the job exits 0. Skipped (77) where
# namespaces cannot be made.
source "$(dirname "$0")/lib.sh"
require_network_namespaces
prefix="awcc$$"
token="$WORK/token"
echo "secret-$$-$RANDOM" > "$token"
chmod 600 "$token"
AURORAWALL="$AW" VIRTUAL_CLUSTER_PREFIX="$prefix" "$SRC_DIR/launch/virtual-cluster" 2 2 -- render \
    --wall "$WALLS/desktop-2x2.toml" --scene "$SCENE" --frames 0 --control-port 5555 --control-bind 198.18.0.1 \
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
from_host1 --token-file "$token" quit || { kill $job; fail "quit refused"; }
status=0; wait $job || status=$?
[ "$status" -eq 0 ] || { cat "$WORK/err"; fail "the job exited $status after quit"; }
[ -z "$(ip netns list | grep "$prefix")" ] || fail "namespaces left behind"
echo "PASS cluster control"
