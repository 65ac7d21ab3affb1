#!/bin/bash
# Change detector, not a correctness test: every shipped camera preset renders the pixels of the images
# in data/presets (192x108), which are this renderer's own output on Mesa's llvmpipe, re-rendered with
# each change that moves them on purpose (git log of data/presets says which). What vouches for the
# pixels is the CPU reference (tests/render/shipped_scenes_test.cpp, reference_ray_test.cpp); this test
# catches a change that moves an image unnoticed. Float reordering inside a component may move a value
# by one half-float step, so HALF_ULPS (default 2) are allowed. Another device rounds differently: where
# EGL does not run on llvmpipe the test is skipped (exit 77).
source "$(dirname "$0")/lib.sh"
HALF_ULPS="${HALF_ULPS:-2}"
wall="$DATA/presets/wall-192x108.toml"
for name in benchmark-view ground-65n low-orbit far-space from-the-moon quiet-arc twilight; do
    out=$(aw_mpirun 1 render --wall "$wall" --scene "$SRC_DIR/config/scenes/$name.toml" --gather --out "$WORK/$name")
    if ! grep -q "backend egl on llvmpipe" <<<"$out"; then
        echo "SKIP: the images are llvmpipe's; EGL runs on $(grep -o 'backend egl on [^(]*' <<<"$out") here"
        exit 77
    fi
    "$COMPARE" diff "$DATA/presets/$name.exr" "$WORK/$name/wall.exr" --half-ulps "$HALF_ULPS" || fail "$name differs"
done
echo "PASS presets"
