#!/bin/bash
# launch/gpu-check --quick on this machine's GL device (Mesa llvmpipe in CI): every check passes, and
# the report names the device and has a row for each check. --skip-tests: ctest runs the gl tier
# (twice) and the shipped scenes itself, so here their rows only have to say that they were skipped.
source "$(dirname "$0")/lib.sh"
"$SRC_DIR/launch/gpu-check" --quick --skip-tests --build "$BUILD_DIR" --out "$WORK/gpu-check" > "$WORK/gpu-check.out" 2>&1 \
    || { cat "$WORK/gpu-check.out"; fail "launch/gpu-check --quick failed"; }
report="$WORK/gpu-check/gpu-check.md"
grep -q "^| device | ok |" "$report" || fail "the report names no device"
for check in "benchmark flight" "flight's frame beyond the draw" "benchmark view" "paper's 20-screen wall as one screen" \
             "cost map" "four ranks on this device"; do
    grep -q "^| $check.* | ok |" "$report" || fail "the report has no passed row '$check'"
done
# Mesa's CPU renderers have no usable timer queries (src/gl/gpu_timer.h): there the GPU's draw time is skipped.
if grep -q "^| device | ok | .*\(llvmpipe\|softpipe\)" "$report"; then
    grep -q "^| flight's GPU draw time (compute) | skip |" "$report" || fail "the GPU's draw time is not skipped on Mesa"
else
    grep -q "^| flight's GPU draw time (compute) | ok |" "$report" || fail "no GPU draw time from timer queries"
fi
for check in "gl tier plasma_gpu_tests (debug modes)" "gl tier render_gl_tests" "shipped scenes vs CPU reference"; do
    grep -q "^| $check | skip |" "$report" || fail "the report does not mark '$check' skipped"
done
[ "$(grep -c ',fail,' "$WORK/gpu-check/gpu-check.csv")" = 0 ] || fail "a check failed"
echo "PASS gpu-check"
