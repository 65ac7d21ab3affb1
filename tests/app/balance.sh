#!/bin/bash
# Dynamic load balancing: the wall rendered with --balance (bands of expensive screens
# drawn by ranks with cheap ones, the split changing every frame) equals the wall rendered
# without it, pixel for pixel, on an uneven wall (3x1, odd sizes) and a 2x2 wall with 3 frames
# so the split has moved away from the static one; and the balanced run's stats show bands
# really moved (some rank sent band pixels). Balancing by work instead of time changes
# nothing either, and the ranks measure the work they drew.
source "$(dirname "$0")/lib.sh"

check_balance() {
    local name="$1" ranks="$2" wall="$WALLS/$1.toml"
    note "$name: $ranks ranks, static and --balance"
    aw_mpirun "$ranks" render --wall "$wall" --scene "$SCENE" --frames 3 --gather --quiet --balance off \
        --out "$WORK/$name-static" --stats "$WORK/$name-static.csv"
    aw_mpirun "$ranks" render --wall "$wall" --scene "$SCENE" --frames 3 --gather --quiet --balance on --balance-bands 5 \
        --out "$WORK/$name-balanced" --stats "$WORK/$name-balanced.csv"
    "$COMPARE" content "$WORK/$name-balanced/wall.exr" "$wall" --min-max 1e-3 --lit-above 5e-4 --min-lit-screens "$ranks"
    "$COMPARE" diff "$WORK/$name-static/wall.exr" "$WORK/$name-balanced/wall.exr" --half-ulps 0
    # Exchanges happened in the balanced run: some rank sent or received band pixels.
    awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i ~ /^exchange_mb_rank/) col[i] = 1; next }
             { for (i in col) if ($i > 0) moved = 1 }
             END { exit moved ? 0 : 1 }' "$WORK/$name-balanced.csv" || fail "$name: no band was exchanged"
}

# Balancing the rays' work (the raymarcher's second output) instead of time only moves bands.
# check_work WALL RANKS PIXELS
check_work() {
    local name="$1" ranks="$2" wall="$WALLS/$1.toml"
    note "$name: $ranks ranks balanced by work"
    aw_mpirun "$ranks" render --wall "$wall" --scene "$SCENE" --frames 3 --gather --quiet --balance on --balance-bands 5 \
        --balance-by work --out "$WORK/$name-work-balanced" --stats "$WORK/$name-work-balanced.csv"
    "$COMPARE" diff "$WORK/$name-static/wall.exr" "$WORK/$name-work-balanced/wall.exr" --half-ulps 0
    # The ranks measured the work they drew: at least one unit per pixel of the wall every frame.
    awk -F, -v pixels="$3" 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i ~ /^render_work_rank/) col[i] = 1; next }
             { work = 0; for (i in col) work += $i; if (work < pixels) low = 1 }
             END { exit low ? 1 : 0 }' "$WORK/$name-work-balanced.csv" || fail "$name: less work than pixels"
}

check_balance desktop-3x1 3
check_balance desktop-2x2 4
check_work desktop-2x2 4 $((4 * 320 * 180))
echo "PASS balance"
