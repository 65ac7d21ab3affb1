#!/bin/bash
# Test 6, GLFW under Xvfb: the 2x2 wall with --backend glfw on 4 ranks opens one window per
# screen (4 windows titled "aurorawall <screen>", counted with xwininfo while it runs) and gathers
# the same wall.exr as the headless EGL backend. Exits 77 (skipped) when xvfb-run is missing.
source "$(dirname "$0")/lib.sh"
wall="$WALLS/desktop-2x2.toml"
args=(render --wall "$wall" --scene "$SCENE" --frames 2 --gather)

if [ "${1:-}" = --inside-x ]; then
    # Runs inside xvfb-run: the render in the background, the windows counted meanwhile.
    out="$2"
    aw_mpirun 4 "${args[@]}" --backend glfw --out "$out" >"$out.log" 2>&1 &
    pid=$!
    most=0
    while kill -0 $pid 2>/dev/null; do
        n=$(xwininfo -root -tree 2>/dev/null | grep -c '"aurorawall ' || true)
        [ "$n" -le "$most" ] || most=$n
        sleep 0.05
    done
    rc=0; wait $pid || rc=$?
    cat "$out.log"
    echo "windows seen at once: $most"
    echo "$most" >"$out.windows"
    exit $rc
fi

if [ -z "${XVFB_RUN:-}" ] || ! [ -x "$XVFB_RUN" ]; then
    echo "SKIP: xvfb-run is not installed"
    exit 77
fi

t0=$(now)
aw_mpirun 4 "${args[@]}" --backend egl --quiet --out "$WORK/egl"
note "egl rendered in $(elapsed "$t0") s"
t0=$(now)
mkdir -p "$WORK/glfw"
"$XVFB_RUN" -a -s "-screen 0 1280x1024x24 $XVFB_OPTIONS" bash "$0" --inside-x "$WORK/glfw"
note "glfw rendered in $(elapsed "$t0") s"
grep -q "backend glfw on " "$WORK/glfw.log" || fail "the start-up line does not name the glfw backend"
[ "$(cat "$WORK/glfw.windows")" = 4 ] || fail "expected 4 windows, saw $(cat "$WORK/glfw.windows") at most"
"$COMPARE" content "$WORK/glfw/wall.exr" "$wall" --min-max 1e-3 --lit-above 5e-4 --min-lit-screens 4
"$COMPARE" diff "$WORK/egl/wall.exr" "$WORK/glfw/wall.exr" --half-ulps 0
echo "PASS glfw"
