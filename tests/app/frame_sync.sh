#!/bin/bash
# Test 4, frame sync: with 4 ranks every rank reports, for every frame, the frame number and the
# animation time the master broadcast: the per-rank columns of --stats equal the frame's, and
# the frames and times follow --start-time and --dt.
source "$(dirname "$0")/lib.sh"
wall="$DATA/tiny-2x2.toml"
ranks=4 frames=5 dt=0.25

# CSV, start time 0.
aw_mpirun $ranks render --wall "$wall" --scene "$SCENE" --frames $frames --dt $dt --start-time 0 \
    --stats "$WORK/s.csv" --quiet --out "$WORK/out"
[ -s "$WORK/s.csv" ] || fail "no $WORK/s.csv"
cat "$WORK/s.csv"
awk -F, -v ranks=$ranks -v frames=$frames -v dt=$dt -v t0=0 '
    function near(a, b) { return (a - b) < 1e-9 && (b - a) < 1e-9 }
    function bad(msg) { print "FAIL: s.csv: " msg > "/dev/stderr"; failed = 1; exit 1 }
    NR == 1 {
        for (i = 1; i <= NF; ++i) col[$i] = i
        if (!("frame" in col) || !("time_s" in col)) bad("no frame or time_s column")
        for (r = 0; r < ranks; ++r)
            if (!(("frame_rank" r) in col) || !(("time_s_rank" r) in col) || !(("render_ms_rank" r) in col))
                bad("columns of rank " r " missing")
        if (("frame_rank" ranks) in col) bad("columns for a rank " ranks " that does not exist")
        next
    }
    {
        n = NR - 2
        if (NF != length(col)) bad("row " NR " has " NF " fields, the header " length(col))
        if ($col["frame"] != n) bad("row " NR ": frame " $col["frame"] ", expected " n)
        if (!near($col["time_s"], t0 + n * dt)) bad("row " NR ": time_s " $col["time_s"] ", expected " t0 + n * dt)
        for (r = 0; r < ranks; ++r) {
            if ($col["frame_rank" r] != $col["frame"]) bad("row " NR ": rank " r " drew frame " $col["frame_rank" r])
            if ($col["time_s_rank" r] != $col["time_s"]) bad("row " NR ": rank " r " drew time " $col["time_s_rank" r])
            if (!($col["render_ms_rank" r] > 0)) bad("row " NR ": rank " r " render_ms " $col["render_ms_rank" r])
        }
    }
    END { if (!failed && NR - 1 != frames) bad(NR - 1 " rows, expected " frames) }
' "$WORK/s.csv"

# JSON, start time 2: read with CMake's string(JSON) (no Python needed).
aw_mpirun $ranks render --wall "$wall" --scene "$SCENE" --frames $frames --dt $dt --start-time 2 \
    --stats "$WORK/s.json" --quiet --out "$WORK/out"
[ -s "$WORK/s.json" ] || fail "no $WORK/s.json"
cat "$WORK/s.json"
"${CMAKE_COMMAND:-cmake}" -DSTATS="$WORK/s.json" -DRANKS=$ranks -DFRAMES=$frames -DDT=$dt -DT0=2 \
    -P "$HERE/check_stats_json.cmake"
echo "PASS frame_sync"
