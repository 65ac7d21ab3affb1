#!/bin/bash
# Test 7, help: the top-level help lists the subcommands, `render --help` mentions every option,
# an unknown subcommand fails.
source "$(dirname "$0")/lib.sh"

top=$("$AW" --help)
echo "$top"
for command in render airmass; do
    grep -Eq "^ +$command " <<<"$top" || fail "aurorawall --help does not list the command '$command'"
done

# render --help runs without mpirun (a singleton MPI process) and prints on rank 0.
render_help=$("$AW" render --help)
echo "$render_help"
for option in help wall scene backend frames dt start-time realtime exposure tonemap out gather tiles \
              single-screen stats data-dir quiet; do
    grep -Eq -e "--$option( |$)" <<<"$render_help" || fail "aurorawall render --help does not mention --$option"
done
# Every option the parser declares, read from its source, so that a new option needs help text.
declared=$(grep -oE '^ *\("[a-z][a-z-]*[",]' "$SRC_DIR/src/app/render_options.cpp" | grep -oE '[a-z][a-z-]*' || true)
[ "$(wc -w <<<"$declared")" -ge 15 ] || fail "could not read the options from src/app/render_options.cpp: $declared"
for option in $declared; do
    grep -Eq -e "--$option( |$)" <<<"$render_help" || fail "aurorawall render --help does not mention --$option"
done
for backend in egl osmesa glfw; do
    grep -q "$backend" <<<"$render_help" || fail "aurorawall render --help does not mention the backend $backend"
done
# And the same through mpirun on 2 ranks: printed once, exit 0.
mpi_help=$(aw_mpirun 2 render --help)
[ "$(grep -c -e '--single-screen' <<<"$mpi_help")" = 1 ] || fail "mpirun -n 2 aurorawall render --help: not printed exactly once"

rc=0
"$AW" bogus >"$WORK/out" 2>"$WORK/err" || rc=$?
cat "$WORK/err"
[ $rc -ne 0 ] || fail "aurorawall bogus exited 0"
grep -q "bogus" "$WORK/err" || fail "aurorawall bogus: the error does not name the command"
rc=0
"$AW" >/dev/null 2>&1 || rc=$?
[ $rc -ne 0 ] || fail "aurorawall without a command exited 0"
echo "PASS help"
