#!/bin/bash
# SIGINT to mpirun (Ctrl-C) ends a running wall cleanly (src/app/stop_signal.h): mpirun passes it
# on as SIGTERM, the master stops at the next frame, and the run's outputs are those of the frames
# drawn: the statistics written as they went (one row per frame), every movie frame complete and
# listed, no temporary file left, and one line saying so. SIGTERM to one rank alone does the same.
# A rank that prints a line a frame, which mpirun stops reading at SIGINT, still stops and writes
# the wall image.
source "$(dirname "$0")/lib.sh"

# A second wall, one of whose ranks gets SIGTERM: the whole wall stops, and says so.
"$MPIEXEC" -n 4 "${MPI_FLAGS[@]}" -x LP_NUM_THREADS=1 "$AW" render --wall "$DATA/tiny-2x2.toml" --scene "$SCENE" \
    --frames 100000 --quiet --stats "$WORK/one.csv" --out "$WORK/one" >"$WORK/one.log" 2>&1 &
one=$!
for _ in $(seq 600); do [ "$(wc -l <"$WORK/one.csv" 2>/dev/null || echo 0)" -ge 4 ] && break; sleep 0.1; done
rank=$(pgrep -P $one | tail -n 1)
[ -n "$rank" ] || fail "no rank of the second wall found"
kill -TERM "$rank"
for _ in $(seq 300); do kill -0 $one 2>/dev/null || break; sleep 0.1; done
kill -0 $one 2>/dev/null && { kill -KILL $one; fail "still running 30 s after SIGTERM to rank pid $rank"; }
wait $one || true
grep -q 'stopped by SIGTERM after [0-9]* frames' "$WORK/one.log" || { cat "$WORK/one.log"; fail "SIGTERM to one rank: no clean stop"; }
note "SIGTERM to one rank (pid $rank) stopped the wall: $(grep -o 'stopped by .*' "$WORK/one.log")"

# One rank of a one-screen wall, fast frames, a line a frame on standard output: mpirun stops reading it
# at SIGINT and sends SIGTERM a second later; the rank must not sit blocked on the full pipe.
"$SRC_DIR/launch/one-screen-wall" 32x18 >"$WORK/tiny-1x1.toml"
"$MPIEXEC" -n 1 "${MPI_FLAGS[@]}" -x LP_NUM_THREADS=1 "$AW" render --wall "$WORK/tiny-1x1.toml" --scene "$SCENE" \
    --frames 100000 --stats "$WORK/loud.csv" --gather --out "$WORK/loud" >"$WORK/loud.log" 2>&1 &
loud=$!
for _ in $(seq 600); do [ "$(wc -l <"$WORK/loud.csv" 2>/dev/null || echo 0)" -ge 6 ] && break; sleep 0.1; done
sleep 1
kill -INT $loud
for _ in $(seq 300); do kill -0 $loud 2>/dev/null || break; sleep 0.1; done
kill -0 $loud 2>/dev/null && { kill -KILL $loud; fail "a rank printing every frame: still running 30 s after SIGINT"; }
wait $loud || true
[ -s "$WORK/loud/wall.exr" ] && [ -s "$WORK/loud/wall.png" ] ||
    { tail -n 5 "$WORK/loud.log"; fail "a rank printing every frame: no wall image after SIGINT ($(ls "$WORK/loud"))"; }
note "a rank printing every frame stopped at SIGINT with its wall image written"

"$MPIEXEC" -n 4 "${MPI_FLAGS[@]}" -x LP_NUM_THREADS=1 "$AW" render --wall "$DATA/tiny-2x2.toml" --scene "$SCENE" \
    --frames 100000 --quiet --stats "$WORK/s.csv" --movie "$WORK/movie" --out "$WORK/out" \
    --record-path "$WORK/flight.toml" >"$WORK/log" 2>&1 &
job=$!
for _ in $(seq 600); do
    [ "$(wc -l <"$WORK/s.csv" 2>/dev/null || echo 0)" -ge 6 ] && [ -s "$WORK/flight.toml" ] && break
    kill -0 $job 2>/dev/null || { cat "$WORK/log"; fail "the wall ended before the signal"; }
    sleep 0.1
done
# The recorded flight is written as it goes (at most a second behind), before the run ends.
[ -s "$WORK/flight.toml" ] || fail "no --record-path file while the wall runs"
grep -q '^\[\[camera.key\]\]' "$WORK/flight.toml" || fail "the recorded flight has no keys: $(head -c 300 "$WORK/flight.toml")"
kill -INT $job
start=$(now)
status=0
for _ in $(seq 300); do kill -0 $job 2>/dev/null || break; sleep 0.1; done
kill -0 $job 2>/dev/null && { kill -KILL $job; fail "still running 30 s after SIGINT"; }
wait $job || status=$?
cat "$WORK/log"
note "ended $(elapsed "$start") s after SIGINT, mpirun exit status $status"
[ $status -ne 0 ] || fail "an interrupted run exited 0"

line=$(grep -o 'stopped by SIGTERM after [0-9]* frames' "$WORK/log") || fail "no line says the run was stopped"
frames=${line//[^0-9]/}
rows=$(($(wc -l <"$WORK/s.csv") - 1))
[ "$rows" -eq "$frames" ] || fail "s.csv has $rows rows for $frames frames drawn"
pngs=$(find "$WORK/movie" -name 'frame-*.png' | wc -l)
listed=$(($(wc -l <"$WORK/movie/frames.csv") - 1))
[ "$pngs" -ge "$((frames - 1))" ] && [ "$listed" -eq "$pngs" ] ||
    fail "$pngs movie frames and $listed listed in frames.csv for $frames frames drawn"
[ -z "$(find "$WORK" -name '*.tmp*')" ] || fail "a temporary file was left: $(find "$WORK" -name '*.tmp*')"
keys=$(grep -c '^\[\[camera.key\]\]' "$WORK/flight.toml")
[ "$keys" -eq "$frames" ] || fail "the recorded flight has $keys keys for $frames frames drawn"
[ -z "$(pgrep -f "$WORK/s.csv")" ] || fail "a rank is still running"
echo "PASS stop_signal ($frames frames, $rows rows, $pngs movie frames)"
