#!/bin/bash
# Bad input: every mistake in a wall file, scene file, option or path ends the run
#   - with the same exit status on EVERY rank: 2 for a usage error (an option, or a rank count
#     other than the wall's), 1 for a runtime failure (a file that cannot be read or written or
#     whose contents are malformed). Each rank's status is recorded by rank_wrapper.sh, which exits
#     0 itself so that mpirun lets every rank finish on its own; a rank killed by a signal or one
#     that never ends (timeout) is a failure,
#   - with exactly one line on the ranks' stderr together: "aurorawall render: ..." naming the file:line
#     (for files whose offending line carries a '# <- error' comment) or the option,
#   - without hanging (timeout 30),
#   - without leaving anything in the --out folder (no wall.exr, wall.png, stats, temporaries).
# Usage: bad_input.sh [main|late-output]   (late-output: mistakes that are only noticed after the
# frames are rendered; see CMakeLists.txt)
source "$(dirname "$0")/lib.sh"
set_name="${1:-main}"
WALL_DATA="$SRC_DIR/tests/wall/data"
TINY="$DATA/tiny-2x2.toml"
failures=0 cases=0

# The line of FILE marked "# <- error".
marked_line() {
    local n; n=$(grep -n -m1 -- '<- error' "$1" | cut -d: -f1)
    [ -n "$n" ] || fail "$1 has no '# <- error' line"
    echo "$n"
}
# The pattern "NAME:LINE:" for a marked file.
at_marked_line() { echo "$(basename "$1"):$(marked_line "$1"):"; }

# expect_error NAME RANKS STATUS REGEX ARGS...: runs mpirun -n RANKS aurorawall render ARGS plus
# --gather, --out OUT and --stats OUT/stats.csv (unless ARGS has its own --out or --stats); every rank
# must exit with STATUS.
expect_error() {
    local name="$1" ranks="$2" status="$3" regex="$4"; shift 4
    local out="$WORK/$name/out" rankdir="$WORK/$name/ranks"
    mkdir -p "$rankdir"
    local args=("$@") has_out=0 has_stats=0 a
    for a in "${args[@]}"; do
        [ "$a" != --out ] || has_out=1
        [ "$a" != --stats ] || has_stats=1
    done
    if [ $has_out = 0 ]; then args+=(--out "$out"); else out=""; fi
    [ $has_stats = 1 ] || args+=(--stats "${out:-$WORK/$name/unused}/stats.csv")
    args+=(--gather)
    cases=$((cases + 1))

    local t0 rc=0 seconds problems=()
    t0=$(now)
    RANK_DIR="$rankdir" timeout 30 "$MPIEXEC" -n "$ranks" "${MPI_FLAGS[@]}" -x LP_NUM_THREADS=1 -x RANK_DIR \
        "$HERE/rank_wrapper.sh" "$AW" render "${args[@]}" >"$WORK/$name/stdout" 2>"$WORK/$name/mpirun-stderr" || rc=$?
    seconds=$(elapsed "$t0")

    [ $rc -ne 124 ] || problems+=("hung: killed by timeout 30")
    [ $rc -eq 0 ] || [ $rc -eq 124 ] || problems+=("mpirun exited $rc although every rank's wrapper exits 0")
    local r rank_rc
    for ((r = 0; r < ranks; ++r)); do
        if [ ! -f "$rankdir/rc.$r" ]; then
            problems+=("rank $r did not exit by itself (killed?)")
        else
            rank_rc=$(cat "$rankdir/rc.$r")
            [ "$rank_rc" = "$status" ] || problems+=("rank $r exited $rank_rc, expected $status")
            [ "$rank_rc" -lt 128 ] || problems+=("rank $r died with status $rank_rc (a signal?)")
        fi
    done
    local stderr_text lines
    stderr_text=$(cat "$rankdir"/stderr.* 2>/dev/null | sed '/^[[:space:]]*$/d')
    lines=$(printf '%s' "$stderr_text" | grep -c '' || true)
    [ "$lines" = 1 ] || problems+=("$lines lines on stderr, expected 1")
    grep -q '^aurorawall render: ' <<<"$stderr_text" || problems+=("stderr does not start with 'aurorawall render: '")
    grep -Eq -e "$regex" <<<"$stderr_text" || problems+=("stderr does not match /$regex/")
    if grep -Eiq 'segmentation|exited on signal|core dumped|terminate called|MPI_ABORT' "$WORK/$name/mpirun-stderr" "$rankdir"/stderr.* 2>/dev/null; then
        problems+=("a crash or abort was reported")
    fi
    if [ -n "$out" ] && [ -e "$out" ] && [ -n "$(ls -A "$out")" ]; then
        problems+=("--out folder not empty: $(ls -A "$out" | tr '\n' ' ')")
    fi

    if [ ${#problems[@]} -eq 0 ]; then
        printf 'ok   %-26s ranks exited %s  %5.2f s  %s\n' "$name" "$(cat "$rankdir"/rc.* | tr '\n' ' ')" "$seconds" "$stderr_text"
    else
        failures=$((failures + 1))
        printf 'FAIL %-26s ranks exited %s  %5.2f s\n' "$name" "$(cat "$rankdir"/rc.* 2>/dev/null | tr '\n' ' ')" "$seconds"
        printf '     command: mpirun -n %s aurorawall render %s\n' "$ranks" "${args[*]}"
        local p; for p in "${problems[@]}"; do printf '     - %s\n' "$p"; done
        printf '     stderr of the ranks:\n%s\n' "$(sed 's/^/       /' <<<"$stderr_text")"
        printf '     stdout:\n%s\n' "$(sed 's/^/       /' "$WORK/$name/stdout")"
    fi
}

main_cases() {
    # Wall files (tests/wall/data, each with its offending line marked): runtime failures.
    local f
    for f in missing-key negative-size unknown-key rank-without-screen grid-rank-gap nan syntax-error \
             eye-behind-wall; do
        expect_error "wall-$f" 4 1 "$(at_marked_line "$WALL_DATA/$f.toml")" --wall "$WALL_DATA/$f.toml" --scene "$SCENE"
    done
    # Two-screen walls, two ranks.
    for f in overlap rank-gap; do
        expect_error "wall-$f" 2 1 "$(at_marked_line "$WALL_DATA/$f.toml")" --wall "$WALL_DATA/$f.toml" --scene "$SCENE"
    done
    expect_error wall-missing-file 4 1 "nonexistent-wall\.toml" --wall "$WORK/nonexistent-wall.toml" --scene "$SCENE"
    # A screen larger than the GL device's render targets: the wall file and the key, before anything is drawn.
    expect_error wall-too-large-for-device 1 1 "huge-screen\.toml: width_px = 65536 is more than this GL device's largest render target" \
        --wall "$DATA/huge-screen.toml" --scene "$SCENE"
    # mpirun -n other than the wall's rank count: a usage error.
    expect_error wall-wrong-rank-count 3 2 "desktop-2x2\.toml.*4 ranks.*3" --wall "$WALLS/desktop-2x2.toml" --scene "$SCENE"
    expect_error wall-ini-file 4 1 "old-desktop-2x2\.ini: INI wall files are no longer read; convert to TOML" \
        --wall "$WALL_DATA/old-desktop-2x2.ini" --scene "$SCENE"
    expect_error wall-ini-syntax 4 1 "$(at_marked_line "$WALL_DATA/old-ini-words.toml").*INI wall files are no longer read" \
        --wall "$WALL_DATA/old-ini-words.toml" --scene "$SCENE"

    # Scene files: runtime failures.
    expect_error scene-missing-file 4 1 "nonexistent-scene\.toml" --wall "$TINY" --scene "$WORK/nonexistent-scene.toml"
    for f in syntax unknown-key nan absurd unknown-component; do
        expect_error "scene-$f" 4 1 "$(at_marked_line "$DATA/bad-$f.toml")" --wall "$TINY" --scene "$DATA/bad-$f.toml"
    done

    # Paths that cannot be read or written: runtime failures.
    expect_error data-dir-missing 4 1 "/nonexistent" --wall "$TINY" --scene "$SCENE" --data-dir /nonexistent
    expect_error out-in-proc 4 1 "--out /proc/forbidden" --wall "$TINY" --scene "$SCENE" --out /proc/forbidden
    touch "$WORK/regular-file"
    expect_error out-under-file 4 1 "--out $WORK/regular-file/sub" --wall "$TINY" --scene "$SCENE" \
        --out "$WORK/regular-file/sub"

    # Options: usage errors.
    expect_error frames-negative 4 2 "--frames" --wall "$TINY" --scene "$SCENE" --frames -1
    expect_error frames-zero-headless 4 2 "--frames 0" --wall "$TINY" --scene "$SCENE" --frames 0
    expect_error frames-fraction 4 2 "--frames" --wall "$TINY" --scene "$SCENE" --frames 1.5
    expect_error backend-vulkan 4 2 "--backend.*vulkan.*egl, osmesa, glfw" --wall "$TINY" --scene "$SCENE" --backend vulkan
    expect_error dt-nan 4 2 "--dt" --wall "$TINY" --scene "$SCENE" --dt nan
    expect_error start-time-inf 4 2 "--start-time" --wall "$TINY" --scene "$SCENE" --start-time inf
    expect_error exposure-negative 4 2 "--exposure" --wall "$TINY" --scene "$SCENE" --exposure -1
    expect_error tonemap-unknown 4 2 "--tonemap.*reinhard.*aces, magnitude-gamma" --wall "$TINY" --scene "$SCENE" \
        --tonemap reinhard
    expect_error option-unknown 4 2 "unrecognised option '--bogus'" --wall "$TINY" --scene "$SCENE" --bogus
    expect_error draw-lanes-removed 4 2 "unrecognised option '--draw-lanes'" --wall "$TINY" --scene "$SCENE" \
        --draw-lanes 1
    expect_error balance-unknown 4 2 "--balance.*maybe.*on, off, auto" --wall "$TINY" --scene "$SCENE" --balance maybe
    expect_error balance-by-unknown 4 2 "--balance-by.*pixels.*time, work" --wall "$TINY" --scene "$SCENE" \
        --balance-by pixels
    expect_error option-twice 4 2 "--wall" --wall "$TINY" --wall "$TINY" --scene "$SCENE"
    expect_error wall-option-missing 4 2 "wall" --scene "$SCENE"
}

# Mistakes in --stats that the program only notices when it writes the file, after rendering.
late_output_cases() {
    touch "$WORK/regular-file"
    expect_error stats-extension 4 2 "--stats" --wall "$TINY" --scene "$SCENE" --frames 3 --stats "$WORK/s.txt"
    expect_error stats-under-file 4 1 "--stats.*regular-file" --wall "$TINY" --scene "$SCENE" --frames 3 \
        --stats "$WORK/regular-file/s.csv"
    expect_error stats-no-folder 4 1 "--stats $WORK/nowhere/s.csv: folder $WORK/nowhere does not exist" \
        --wall "$TINY" --scene "$SCENE" --frames 3 --stats "$WORK/nowhere/s.csv"
    mkdir -p "$WORK/a-folder.csv"
    expect_error stats-is-folder 4 1 "--stats $WORK/a-folder.csv: is a folder" --wall "$TINY" --scene "$SCENE" \
        --frames 3 --stats "$WORK/a-folder.csv"
    expect_error record-unwritable 4 1 "--record-path /proc/flight.toml: folder /proc" --wall "$TINY" \
        --scene "$SCENE" --frames 3 --record-path /proc/flight.toml
    expect_error cost-map-no-folder 4 1 "--cost-map $WORK/nowhere/c.png: folder $WORK/nowhere does not exist" \
        --wall "$TINY" --scene "$SCENE" --frames 3 --cost-map "$WORK/nowhere/c.png"
    # One screen's tile name taken by a folder: refused before the first frame, nothing written.
    local tiles="$WORK/tiles-blocked/out"
    mkdir -p "$tiles/tile-r1c0.exr"
    expect_error tiles-blocked 4 1 "--tiles $tiles/tile-r1c0.exr: is a folder, not a file" --wall "$TINY" \
        --scene "$SCENE" --frames 1 --tiles --out "$tiles" --stats "$WORK/tiles-blocked/stats.csv"
    if [ "$(ls -A "$tiles")" != "tile-r1c0.exr" ]; then
        echo "FAIL tiles-blocked: left in the output folder: $(ls -A "$tiles" | tr '\n' ' ')"
        failures=$((failures + 1))
    fi
    # The same for the gathered wall's PNG: no wall.exr written either.
    local gathered="$WORK/png-blocked/out"
    mkdir -p "$gathered/wall.png"
    expect_error png-blocked 4 1 "--gather $gathered/wall.png: is a folder, not a file" --wall "$TINY" \
        --scene "$SCENE" --frames 1 --out "$gathered" --stats "$WORK/png-blocked/stats.csv"
    if [ "$(ls -A "$gathered")" != "wall.png" ]; then
        echo "FAIL png-blocked: left in the output folder: $(ls -A "$gathered" | tr '\n' ' ')"
        failures=$((failures + 1))
    fi
}

case "$set_name" in
    main) main_cases ;;
    late-output) late_output_cases ;;
    *) fail "unknown case set $set_name" ;;
esac
echo "$((cases - failures)) of $cases cases ok"
[ $failures -eq 0 ] || fail "$failures bad-input cases misbehaved"
echo "PASS bad_input $set_name"
