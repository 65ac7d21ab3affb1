#!/bin/bash
# Runs one MPI rank of a command with its stderr in $RANK_DIR/stderr.<rank> and its exit status in
# $RANK_DIR/rc.<rank>, then exits 0: so that mpirun does not kill the other ranks as soon as the
# first one exits non-zero, and a test can check what EVERY rank printed and how it exited.
rank="${OMPI_COMM_WORLD_RANK:-${PMIX_RANK:-x}}"
"$@" 2>"$RANK_DIR/stderr.$rank"
echo "$?" >"$RANK_DIR/rc.$rank"
exit 0
