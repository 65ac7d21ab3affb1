#!/bin/bash
# The wall as a Slurm batch job (launch/slurm/aurorawall.sbatch). Usage: slurm.sh script|cluster
#   script   without Slurm: the srun command line it generates (--dry-run) for the paper's wall and a
#            small one, the one-line error (exit 2) for a task count other than the wall's, outside
#            a job and for a malformed option; launch/rank-display's DISPLAY and EGL device per task.
#   cluster  a one-node Slurm on this machine (launch/slurm/local-cluster): sbatch runs a 2x2 wall as
#            4 tasks whose gathered image equals the one of mpirun -n 4 bit for bit; a job of 3
#            tasks ends with the one-line error and status 2 before srun; srun --gpus-per-task 1 on 4
#            stand-in GPUs gives task i EGL device i. Skipped (77) without Slurm (slurm-wlm) or
#            network namespaces, or where Slurm does not come up.
source "$(dirname "$0")/lib.sh"
sbatch_script="$SRC_DIR/launch/slurm/aurorawall.sbatch"
tiny="$DATA/tiny-2x2.toml"
export AURORAWALL="$AW"
unset SLURM_JOB_ID SLURM_NTASKS SLURM_GPUS_PER_TASK SLURM_PROCID CUDA_VISIBLE_DEVICES AURORAWALL_EGL_DEVICE DISPLAYS

if [ "${1:-}" = script ]; then
    note "--dry-run: the paper's wall, 10 tasks of 1 GPU"
    line=$(cd "$SRC_DIR" && "$sbatch_script" --dry-run)
    echo "$line"
    expected="srun --ntasks 10 --gpus-per-task 1 --mpi pmix --kill-on-bad-exit=1 $SRC_DIR/launch/rank-display $AW render --wall config/walls/uaf-powerwall.toml --scene config/scenes/substorm.toml "
    [ "$line" = "$expected" ] || fail "dry run: expected '$expected'"

    note "render --print-ranks: the count the task count is checked against"
    [ "$("$AW" render --wall "$SRC_DIR/config/walls/uaf-powerwall.toml" --scene "$SCENE" --print-ranks)" = 10 ] ||
        fail "uaf-powerwall: not 10 ranks"
    [ "$("$AW" render --wall "$SRC_DIR/config/walls/uaf-powerwall.toml" --scene "$SCENE" --single-screen --print-ranks)" = 1 ] ||
        fail "uaf-powerwall --single-screen: not 1 rank"

    note "--dry-run inside a job of 4 tasks without GPUs, render options passed on"
    line=$(SLURM_NTASKS=4 SLURM_MPI_TYPE=pmi2 "$sbatch_script" --dry-run "$tiny" "$SCENE" --gather --out "$WORK/o")
    echo "$line"
    expected="srun --ntasks 4 --mpi pmi2 --kill-on-bad-exit=1 $SRC_DIR/launch/rank-display $AW render --wall $tiny --scene $SCENE --gather --out $WORK/o "
    [ "$line" = "$expected" ] || fail "dry run in a job: expected '$expected'"

    note "bad input: one line, exit 2"
    expect_usage_error() {
        local wanted="$1"; shift
        local code=0 out
        out=$("$@" 2>&1) || code=$?
        echo "$out"
        [ $code -eq 2 ] || fail "exit $code, expected 2: $*"
        [ "$out" = "$wanted" ] || fail "expected the one line '$wanted'"
    }
    expect_usage_error "launch/slurm/aurorawall.sbatch: $tiny is driven by 4 ranks, but the job has 3 tasks (sbatch --ntasks 4)" \
        env SLURM_NTASKS=3 "$sbatch_script" --dry-run "$tiny" "$SCENE"
    expect_usage_error "launch/slurm/aurorawall.sbatch: not inside a Slurm job (submit it with sbatch, or use --dry-run)" \
        "$sbatch_script" "$tiny" "$SCENE"
    expect_usage_error "aurorawall render: unrecognised option '--bogus' (see aurorawall render --help)" \
        "$sbatch_script" --dry-run "$tiny" "$SCENE" --bogus

    note "rank-display: a task's DISPLAY and EGL device"
    show() { env -u DISPLAY "$@" "$SRC_DIR/launch/rank-display" sh -c 'echo "${DISPLAY:-none} ${AURORAWALL_EGL_DEVICE:-none}"'; }
    [ "$(show SLURM_JOB_ID=7 SLURM_PROCID=2 CUDA_VISIBLE_DEVICES=3,1 DISPLAYS=:0,:0.1,:1)" = ":1 3" ] ||
        fail "task 2 with GPUs 3,1: not DISPLAY :1 and EGL device 3"
    [ "$(show SLURM_JOB_ID=7 SLURM_PROCID=0 CUDA_VISIBLE_DEVICES=2 AURORAWALL_EGL_DEVICE=5)" = "none 5" ] ||
        fail "a given AURORAWALL_EGL_DEVICE was replaced"
    [ "$(show SLURM_JOB_ID=7 SLURM_PROCID=1)" = "none none" ] || fail "a task without a GPU got an EGL device"
    [ "$(show CUDA_VISIBLE_DEVICES=1)" = "none none" ] || fail "outside Slurm, CUDA_VISIBLE_DEVICES chose the EGL device"
    code=0; out=$(show SLURM_JOB_ID=7 SLURM_PROCID=1 CUDA_VISIBLE_DEVICES=GPU-4a1b 2>&1) || code=$?
    echo "$out"
    [ $code -eq 1 ] && [ "$(wc -l <<<"$out")" = 1 ] || fail "a GPU named by UUID: exit $code, expected one line and 1"
    echo "PASS slurm script"
    exit 0
fi

[ "${1:-}" = cluster ] || fail "usage: slurm.sh script|cluster"
command -v slurmctld >/dev/null && command -v slurmd >/dev/null && command -v sbatch >/dev/null ||
    { echo "SKIPPED: Slurm is not installed (slurm-wlm; launch/install-deps installs it)"; exit 77; }
require_network_namespaces
export OMPI_MCA_pml=ob1 OMPI_MCA_btl=self,vader LP_NUM_THREADS=1

note "the reference: mpirun -n 4 on this host"
aw_mpirun 4 render --wall "$tiny" --scene "$SCENE" --gather --quiet --out "$WORK/mpirun"

cat > "$WORK/jobs.sh" <<JOBS
set -u
cd "$SRC_DIR"   # sbatch is submitted from the repository's root
srun -n 4 --gpus-per-task 1 launch/rank-display sh -c 'echo "task \$SLURM_PROCID egl \$AURORAWALL_EGL_DEVICE"' |
    sort > "$WORK/devices"
sbatch --wait --ntasks 4 --gpus-per-task 0 --output "$WORK/job.out" "$sbatch_script" "$tiny" "$SCENE" \
    --gather --quiet --out "$WORK/slurm"
echo \$? > "$WORK/job.status"
sbatch --wait --ntasks 3 --gpus-per-task 0 --output "$WORK/job3.out" "$sbatch_script" "$tiny" "$SCENE"
echo \$? > "$WORK/job3.status"
JOBS
started=$(now)
code=0
"$SRC_DIR/launch/slurm/local-cluster" --gpus 4 -- bash "$WORK/jobs.sh" 2> "$WORK/cluster.err" || code=$?
cat "$WORK/cluster.err"
if grep -q "Slurm did not come up" "$WORK/cluster.err"; then
    echo "SKIPPED: the one-node Slurm did not start here"
    exit 77
fi
[ $code -eq 0 ] || fail "launch/slurm/local-cluster exited $code"
echo "Slurm's part took $(elapsed "$started") s"

note "srun --gpus-per-task 1: task i on EGL device i"
cat "$WORK/devices"
[ "$(cat "$WORK/devices")" = "$(printf 'task %d egl %d\n' 0 0 1 1 2 2 3 3)" ] || fail "wrong EGL devices"

note "sbatch --ntasks 4: the wall"
cat "$WORK/job.out"
[ "$(cat "$WORK/job.status")" = 0 ] || fail "the job failed (sbatch --wait exit $(cat "$WORK/job.status"))"
"$COMPARE" diff "$WORK/mpirun/wall.exr" "$WORK/slurm/wall.exr" --half-ulps 0 || fail "differs from mpirun -n 4"

note "sbatch --ntasks 3: one line, status 2"
cat "$WORK/job3.out"
[ "$(cat "$WORK/job3.status")" = 2 ] || fail "sbatch --wait exit $(cat "$WORK/job3.status"), expected 2"
[ "$(cat "$WORK/job3.out")" = "launch/slurm/aurorawall.sbatch: $tiny is driven by 4 ranks, but the job has 3 tasks (sbatch --ntasks 4)" ] ||
    fail "not the one-line error"
[ -z "$(ip netns list | grep awslurm)" ] || fail "a namespace left behind"
echo "PASS slurm cluster"
