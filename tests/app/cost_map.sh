#!/bin/bash
# render --cost-map: the benchmark view on the 2x2 desktop wall (4 ranks). The PNG is the wall plus
# its scale bar, every wall pixel is a colour of the map, and the curtains (brightest green radiance
# in wall.exr) sit higher on the map, i.e. cost more, than the empty sky.
source "$(dirname "$0")/lib.sh"
: "${CHECK_COST_MAP:?}"
wall="$WALLS/desktop-2x2.toml"

t0=$(now)
# Two frames at one time: the second, timed without shader compilation, is the one mapped.
aw_mpirun 4 render --wall "$wall" --scene "$SRC_DIR/config/scenes/benchmark-view.toml" --frames 2 --dt 0 \
    --gather --quiet --out "$WORK/out" --cost-map "$WORK/out/cost.png"
note "rendered in $(elapsed "$t0") s"
[ -s "$WORK/out/cost.png" ] || fail "no cost map written"
ls "$WORK/out"/.*tmp* >/dev/null 2>&1 && fail "a temporary file was left behind"
"$CHECK_COST_MAP" "$WORK/out/cost.png" "$WORK/out/wall.exr" || fail "cost map does not follow the curtains"

# The balanced split is refused with a usage error naming the option, before anything is written.
status=0
aw_mpirun 2 render --wall "$wall" --scene "$SCENE" --balance on --out "$WORK/refused" \
    --cost-map "$WORK/refused/cost.png" 2>"$WORK/err" || status=$?
[ "$status" -eq 2 ] || fail "--cost-map with --balance on exited $status, expected 2"
grep -q -- "--cost-map" "$WORK/err" || fail "the error does not name --cost-map: $(cat "$WORK/err")"
[ ! -e "$WORK/refused/cost.png" ] || fail "a cost map was written after a usage error"
echo "PASS cost_map"
