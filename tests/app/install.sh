#!/bin/bash
# Test 8, install: `cmake --install` into a fresh prefix; the installed binary, run from a folder
# outside the source and build trees with AURORAWALL_DATA_DIR unset, renders one frame of the
# installed single.toml wall and substorm scene, reading the shaders from PREFIX/share/aurorawall
# (shown by removing an installed shader module: the run must then fail naming the prefix).
source "$(dirname "$0")/lib.sh"
: "${BUILD_DIR:?}"
unset AURORAWALL_DATA_DIR
prefix="$WORK/prefix"

"${CMAKE_COMMAND:-cmake}" --install "$BUILD_DIR" --prefix "$prefix" >"$WORK/install.log" \
    || { cat "$WORK/install.log"; fail "cmake --install failed"; }
installed="$prefix/bin/aurorawall"
share="$prefix/share/aurorawall"
[ -x "$installed" ] || fail "no $installed"
for f in "$share/config/walls/single.toml" "$share/config/scenes/substorm.toml"; do
    [ -f "$f" ] || fail "not installed: $f"
done
[ -n "$(find "$share/shaders" -name '*.glsl' | head -1)" ] || fail "no shaders installed under $share/shaders"

mkdir -p "$WORK/elsewhere"
cd "$WORK/elsewhere"
AW="$installed"
t0=$(now)
aw_mpirun 1 render --wall "$share/config/walls/single.toml" --scene "$share/config/scenes/substorm.toml" \
    --gather --out out | tee render.log
note "rendered in $(elapsed "$t0") s"
[ -s out/wall.exr ] && [ -s out/wall.png ] || fail "no out/wall.exr or out/wall.png"
"$COMPARE" content out/wall.exr "$share/config/walls/single.toml" --min-max 1e-3 --lit-above 5e-5 --min-lit-screens 1

# The shaders it used were the installed ones: with the installed modules removed (the folder
# stays) it must fail and say where it looked, not fall back to the source tree unnoticed.
find "$share/shaders" -name '*.glsl' -delete
rc=0
aw_mpirun 1 render --wall "$share/config/walls/single.toml" --scene "$share/config/scenes/substorm.toml" \
    --out out2 >"$WORK/missing.out" 2>"$WORK/missing.err" || rc=$?
grep -v '^-\|^$' "$WORK/missing.err" | head -3
[ $rc -ne 0 ] || fail "still renders without the installed shader modules: they are not the ones it used"
grep -q "$share/shaders" "$WORK/missing.err" || fail "the error does not name the installed shader folder $share/shaders"
echo "PASS install"
