#!/bin/bash
# Every rank's GL device, named on the master: with --verbose the devices and their ranks; a wall whose
# ranks draw on different devices is warned of on stderr (their tiles can differ in the last bits at
# the seams) and still runs. Here two llvmpipe vector widths stand in for two kinds of GPU: llvmpipe
# names its width in GL_RENDERER.
source "$(dirname "$0")/lib.sh"
wall="$WALLS/desktop-3x1.toml"

out=$(aw_mpirun 3 render --wall "$wall" --scene "$SCENE" --frames 1 --verbose --out "$WORK/same" 2>&1) ||
    { echo "$out"; fail "the wall did not run"; }
grep -E -q "devices: llvmpipe [^;]* \(ranks 0-2\)" <<<"$out" || { echo "$out"; fail "--verbose does not name the ranks' device"; }
! grep -q "different GL devices" <<<"$out" || { echo "$out"; fail "one device, yet a warning of different ones"; }

args=(render --wall "$wall" --scene "$SCENE" --frames 1 --quiet --gather --out "$WORK/mixed")
out=$("$MPIEXEC" "${MPI_FLAGS[@]}" -x LP_NUM_THREADS=1 -n 1 -x LP_NATIVE_VECTOR_WIDTH=256 "$AW" "${args[@]}" : \
      -n 2 -x LP_NATIVE_VECTOR_WIDTH=128 "$AW" "${args[@]}" 2>&1) || { echo "$out"; fail "the mixed wall did not run"; }
echo "$out"
grep -E -q "aurorawall: warning: the ranks draw on different GL devices: llvmpipe .*256 bits\) \(rank 0\); llvmpipe .*128 bits\) \(ranks 1-2\); " <<<"$out" ||
    fail "no warning naming each device's ranks"
[ -s "$WORK/mixed/wall.exr" ] || fail "the mixed wall wrote no wall.exr"
echo "PASS devices"
