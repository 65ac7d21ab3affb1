#!/bin/bash
# Regression: every shipped camera preset renders the same pixels as the images in data/presets,
# rendered at 192x108 by the code before the components became plug-ins (twilight re-rendered
# after its sky air became the atmosphere's: docs/aurora-physics.md shows before and after; every preset
# with curtains re-rendered when the march began to integrate each step across the curtains, and
# those with fluid detail when its sub-steps began to resolve the detail's cells along and again
# when steps running along a curtain began to be integrated along it, and all when the emission
# began to be read from one row per curtain and shared by runs of sub-steps (at most 3 half-float
# steps each), and all with curtains when the default step became 16 km with finer sub-steps and
# again when the sub-steps came to cover only the part of a step within a curtain's reach, and
# those with curtains of several thicknesses when each curtain came to emit within its own reach, and
# all with detail when that reach came to follow the detail phase, and those with curtains when the
# default step became 12 km with sub-steps of 0.75 detail cells, and all when each pixel came to sum
# the stars of the neighbouring cells, and those with fluid detail when its flux came to be integrated
# exactly along each ray's path through the detail's cells; their
# accuracy tests/render/reference_ray_test.cpp checks against the CPU reference). Float
# reordering inside a component may move a value by one half-float step, so HALF_ULPS (default 2)
# are allowed.
source "$(dirname "$0")/lib.sh"
HALF_ULPS="${HALF_ULPS:-2}"
wall="$DATA/presets/wall-192x108.toml"
for name in benchmark-view ground-65n low-orbit far-space quiet-arc twilight; do
    aw_mpirun 1 render --wall "$wall" --scene "$SRC_DIR/config/scenes/$name.toml" --gather --quiet --out "$WORK/$name"
    "$COMPARE" diff "$DATA/presets/$name.exr" "$WORK/$name/wall.exr" --half-ulps "$HALF_ULPS" || fail "$name differs"
done
echo "PASS presets"
