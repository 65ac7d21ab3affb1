#!/bin/bash
# The distributed path on a virtual cluster (launch/virtual-cluster: one network namespace per host,
# Open MPI over TCP only, its daemons started on the other hosts through an rsh agent): a 2x2 wall on
# 2 hosts x 2 ranks, the same with --balance (bands cross hosts), and on 4 hosts x 1 rank, each
# gives the image of the one-host run and of --single-screen on one rank bit for bit. No namespace is
# left behind. Skipped (77) where namespaces cannot be made (not root, or no ip netns).
source "$(dirname "$0")/lib.sh"
require_network_namespaces
wall="$WALLS/desktop-2x2.toml"
cluster() { AURORAWALL="$AW" VIRTUAL_CLUSTER_PREFIX="awvct$$" "$SRC_DIR/launch/virtual-cluster" "$@"; }

note "one host, 4 ranks (shared memory), and --single-screen on 1 rank"
aw_mpirun 4 render --wall "$wall" --scene "$SCENE" --gather --quiet --out "$WORK/local"
aw_mpirun 4 render --wall "$wall" --scene "$SCENE" --gather --balance on --quiet --out "$WORK/local-balanced"
aw_mpirun 1 render --wall "$wall" --scene "$SCENE" --single-screen --gather --quiet --out "$WORK/single"

for run in "2 2" "2 2 balanced" "4 1"; do
    set -- $run
    name="$1x$2${3:+-$3}"
    note "$1 hosts x $2 ranks${3:+, --balance on}"
    cluster "$1" "$2" -- render --wall "$wall" --scene "$SCENE" --gather ${3:+--balance on} --quiet \
        --out "$WORK/$name" || fail "$name: the job failed"
    "$COMPARE" diff "$WORK/local${3:+-balanced}/wall.exr" "$WORK/$name/wall.exr" --half-ulps 0 ||
        fail "$name: differs from the one-host run"
    "$COMPARE" diff "$WORK/single/wall.exr" "$WORK/$name/wall.exr" --half-ulps 0 ||
        fail "$name: differs from --single-screen"
done
[ -z "$(ip netns list | grep "awvct$$")" ] || fail "namespaces left behind"
echo "PASS virtual cluster"
