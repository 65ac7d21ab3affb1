#!/bin/bash
# Test 3, EGL vs OSMesa: the same wall rendered with either headless backend gives identical
# pixels, tile by tile and gathered, where both are Mesa's llvmpipe; where EGL finds a GPU the two are
# different devices, and the test is skipped (exit 77; the GPU is held to the CPU reference elsewhere).
source "$(dirname "$0")/lib.sh"
wall="$WALLS/desktop-3x1.toml"

for backend in egl osmesa; do
    t0=$(now)
    out=$(aw_mpirun 3 render --wall "$wall" --scene "$SCENE" --backend "$backend" --gather --tiles \
              --out "$WORK/$backend")
    echo "$out"
    # Guard against a backend option that is silently ignored: the start-up line names it.
    grep -q "backend $backend on " <<<"$out" || fail "--backend $backend: the start-up line does not name it"
    if [ $backend = egl ] && ! grep -q "backend egl on llvmpipe" <<<"$out"; then
        echo "SKIP: EGL runs on a GPU here, OSMesa on llvmpipe: two devices, not bit-identical"
        exit 77
    fi
    note "$backend rendered in $(elapsed "$t0") s"
done
"$COMPARE" content "$WORK/egl/wall.exr" "$wall" --min-max 1e-3 --lit-above 5e-4 --min-lit-screens 3
"$COMPARE" diff "$WORK/egl/wall.exr" "$WORK/osmesa/wall.exr" --half-ulps 0
for tile in "$WORK"/egl/tile-*.exr; do
    "$COMPARE" diff "$tile" "$WORK/osmesa/$(basename "$tile")" --half-ulps 0
done
[ "$(ls "$WORK"/egl/tile-*.exr | wc -l)" -eq 3 ] || fail "expected 3 tiles from egl"
echo "PASS backends"
