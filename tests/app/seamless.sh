#!/bin/bash
# Test 1, seamless wall: a wall rendered one rank per screen and gathered equals the same canvas
# rendered as one screen on one rank (--single-screen). Rays are built so that both compute the
# same bits; the EXR stores half floats, so HALF_ULPS (default 1) half-float steps are allowed.
# Also: the image has structure in every screen and no non-finite or clamped values, and every
# --tiles EXR equals its part of the reference.
# Arguments (optional): another scene in tests/app/data (e.g. the glory on the seams), and at most how
# many screens need structure (0 for a scene whose screens are all bright deck: the diff still checks).
source "$(dirname "$0")/lib.sh"
HALF_ULPS="${HALF_ULPS:-1}"
[ $# -gt 0 ] && SCENE="$DATA/$1"
MAX_LIT_SCREENS="${2:-99}"

check_wall() {
    local name="$1" ranks="$2" wall="$WALLS/$1.toml"
    local lit=$(( ranks < MAX_LIT_SCREENS ? ranks : MAX_LIT_SCREENS ))
    note "$name: $ranks ranks, --gather --tiles"
    local t0; t0=$(now)
    aw_mpirun "$ranks" render --wall "$wall" --scene "$SCENE" --gather --tiles --quiet --out "$WORK/$name-wall"
    note "$name: wall rendered in $(elapsed "$t0") s; --single-screen on 1 rank"
    t0=$(now)
    aw_mpirun 1 render --wall "$wall" --scene "$SCENE" --single-screen --gather --quiet --out "$WORK/$name-single"
    note "$name: reference rendered in $(elapsed "$t0") s"
    for f in wall.exr wall.png; do
        [ -s "$WORK/$name-wall/$f" ] || fail "$name: $f missing or empty"
    done
    "$COMPARE" content "$WORK/$name-wall/wall.exr" "$wall" --min-max 1e-3 --lit-above 5e-4 --min-lit-screens "$lit"
    "$COMPARE" content "$WORK/$name-single/wall.exr" "$wall" --min-max 1e-3 --lit-above 5e-4 --min-lit-screens "$lit"
    "$COMPARE" diff "$WORK/$name-single/wall.exr" "$WORK/$name-wall/wall.exr" --half-ulps "$HALF_ULPS"
    "$COMPARE" tiles "$wall" "$WORK/$name-single/wall.exr" "$WORK/$name-wall" --half-ulps "$HALF_ULPS"
}

check_wall desktop-2x2 4
check_wall desktop-3x1 3
echo "PASS seamless"
