#!/bin/bash
# launch/gpu-check --quick on this machine's GL device (Mesa llvmpipe in CI): every check passes, and
# the report names the device and has a row for each check.
source "$(dirname "$0")/lib.sh"
"$SRC_DIR/launch/gpu-check" --quick --build "$BUILD_DIR" --out "$WORK/gpu-check" > "$WORK/gpu-check.out" 2>&1 \
    || { cat "$WORK/gpu-check.out"; fail "launch/gpu-check --quick failed"; }
report="$WORK/gpu-check/gpu-check.md"
grep -q "^| device | ok |" "$report" || fail "the report names no device"
for check in "gl tier plasma_gpu_tests (debug modes)" "shipped scenes vs CPU reference" "benchmark flight" \
             "benchmark view" "paper's 20-screen wall as one screen"; do
    grep -q "^| $check" "$report" || fail "the report has no row '$check'"
done
[ "$(grep -c ',fail,' "$WORK/gpu-check/gpu-check.csv")" = 0 ] || fail "a check failed"
echo "PASS gpu-check"
