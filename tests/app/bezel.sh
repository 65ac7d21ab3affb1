#!/bin/bash
# Test 2, bezels: a wall with bezel gaps of whole pixels, gathered, equals its --single-screen
# render on the screens, and is exactly black on the bezels (which the reference shows lit).
source "$(dirname "$0")/lib.sh"
HALF_ULPS="${HALF_ULPS:-1}"
wall="$WALLS/desktop-2x2-bezel.toml"

t0=$(now)
aw_mpirun 4 render --wall "$wall" --scene "$SCENE" --gather --quiet --out "$WORK/wall"
note "wall rendered in $(elapsed "$t0") s"
t0=$(now)
aw_mpirun 1 render --wall "$wall" --scene "$SCENE" --single-screen --gather --quiet --out "$WORK/single"
note "reference rendered in $(elapsed "$t0") s"
"$COMPARE" content "$WORK/wall/wall.exr" "$wall" --min-max 1e-3 --lit-above 5e-4 --min-lit-screens 4
"$COMPARE" bezel "$wall" "$WORK/single/wall.exr" "$WORK/wall/wall.exr" --half-ulps "$HALF_ULPS"
echo "PASS bezel"
