#!/bin/bash
# Help and the command-line convention: the top-level help lists the commands and the exit status,
# `render --help` mentions every option; for every command (and aurorawall itself) --help prints
# usage on stdout with status 0, an unknown option exits 2 with one line on stderr naming it, a word
# not among an option's choices exits 2 naming the option and the allowed words, and a runtime
# failure exits 1 with one line.
source "$(dirname "$0")/lib.sh"

top=$("$AW" --help)
echo "$top"
for command in render airmass tables accuracy mie plasma; do
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
declared=$(grep -oE '^ *\("[a-z][a-z-]*[",]|addChoice\("[a-z-]+"' "$SRC_DIR/src/app/render_options.cpp" |
           sed 's/addChoice//' | grep -oE '[a-z][a-z-]*' || true)
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

# expect STATUS REGEX COMMAND...: runs aurorawall COMMAND (stdin from $STDIN, default empty); it must
# exit with STATUS, and for STATUS != 0 print exactly one line on stderr matching REGEX and nothing on
# stdout; for 0, usage on stdout matching REGEX and nothing on stderr.
expect() {
    local status="$1" regex="$2"; shift 2
    local rc=0
    "$AW" "$@" <"${STDIN:-/dev/null}" >"$WORK/out" 2>"$WORK/err" || rc=$?
    local what="aurorawall $*"
    [ "$rc" = "$status" ] || fail "$what: exit status $rc, expected $status; stderr: $(cat "$WORK/err")"
    if [ "$status" = 0 ]; then
        grep -q "Usage" "$WORK/out" || fail "$what: no usage on stdout"
        grep -Eq -e "$regex" "$WORK/out" || fail "$what: stdout does not match /$regex/"
        [ ! -s "$WORK/err" ] || fail "$what: wrote on stderr: $(cat "$WORK/err")"
    else
        [ "$(grep -c '' "$WORK/err")" = 1 ] || fail "$what: $(grep -c '' "$WORK/err") lines on stderr, expected 1"
        grep -Eq -e "$regex" "$WORK/err" || fail "$what: stderr does not match /$regex/: $(cat "$WORK/err")"
        [ ! -s "$WORK/out" ] || fail "$what: wrote on stdout: $(head -c 200 "$WORK/out")"
    fi
    echo "ok   $status  $what: $(head -1 "$WORK/err")"
}

# aurorawall itself.
expect 0 "Exit status" --help
expect 2 "^aurorawall: unrecognised option '--bogus'" --bogus
expect 2 "^aurorawall: unknown command 'bogus' \(allowed: render, airmass, tables, accuracy, mie, plasma\)" bogus
expect 2 "^aurorawall: missing command" 

# render (a singleton MPI process without mpirun).
expect 0 "--backend" render --help
expect 2 "^aurorawall render: unrecognised option '--bogus'" render --bogus
expect 2 "^aurorawall render: --backend: unknown value 'vulkan' \(allowed: egl, osmesa, glfw\)" \
    render --wall "$DATA/tiny-2x2.toml" --scene "$SCENE" --backend vulkan
expect 1 "^aurorawall render: .*nonexistent-wall\.toml" render --wall "$WORK/nonexistent-wall.toml" --scene "$SCENE"

# render: an output at the path of an input (the scene, a base scene, the wall) or of another output
# is a usage error, before anything is read or written; a --movie folder that holds a movie's files,
# an over-long control secret and an unwritable standard output are runtime failures.
single="$WALLS/single.toml"
cp "$SCENE" "$WORK/flight.toml"
printf '[scene]\nbase = "flight.toml"\n' > "$WORK/derived.toml"
cp "$single" "$WORK/wall.toml"
expect 2 "^aurorawall render: --record-path .*/flight.toml would overwrite the --scene file" \
    render --wall "$single" --scene "$WORK/flight.toml" --record-path "$WORK/flight.toml"
expect 2 "^aurorawall render: --record-path .*/flight.toml would overwrite a base scene of --scene" \
    render --wall "$single" --scene "$WORK/derived.toml" --record-path "$WORK/./flight.toml"
expect 2 "^aurorawall render: --record-path .*/wall.toml would overwrite the --wall file" \
    render --wall "$WORK/wall.toml" --scene "$SCENE" --record-path "$WORK/wall.toml"
cmp -s "$SCENE" "$WORK/flight.toml" && cmp -s "$single" "$WORK/wall.toml" ||
    fail "render --record-path onto an input changed it"
expect 2 "^aurorawall render: --gather .*/clash/wall.png is the file of --cost-map .*/clash/wall.png: give them different paths" \
    render --wall "$single" --scene "$SCENE" --gather --out "$WORK/clash" --cost-map "$WORK/clash/wall.png"
expect 2 "^aurorawall render: --cost-map .*/film/frame-000000.png is a file the --movie folder's frames write" \
    render --wall "$single" --scene "$SCENE" --movie "$WORK/film" --cost-map "$WORK/film/frame-000000.png"
expect 2 "^aurorawall render: --stats .*/reel.csv is the --movie folder: give them different paths" \
    render --wall "$single" --scene "$SCENE" --movie "$WORK/reel.csv" --stats "$WORK/reel.csv"
expect 2 "^aurorawall render: --cost-map .*/shots.png is the --out folder: give them different paths" \
    render --wall "$single" --scene "$SCENE" --gather --out "$WORK/shots.png/" --cost-map "$WORK/shots.png"
for folder in clash film reel.csv shots.png; do
    [ ! -e "$WORK/$folder" ] || fail "render with clashing outputs created $folder"
done
# Two 1-pixel screens 1 km apart: a canvas of 1000001x1000001 pixels, 32 TB to assemble on rank 0.
cat > "$WORK/sparse.toml" <<'EOF'
[ranks]
screens_per_rank = 2
[[screen]]
name = "a"
width_px = 1
height_px = 1
width_mm = 1
height_mm = 1
x_mm = 0
y_mm = 0
[[screen]]
name = "b"
width_px = 1
height_px = 1
width_mm = 1
height_mm = 1
x_mm = 1000000
y_mm = 1000000
[eye]
z_mm = 500000
EOF
for option in "--gather" "--movie $WORK/sparse-movie" "--cost-map $WORK/sparse.png"; do
    # shellcheck disable=SC2086 # the words of $option are the option and its value
    expect 1 "^aurorawall render: ${option%% *}: the wall canvas of 1000001x1000001 pixels needs about 29802.4 GiB on rank 0" \
        render --wall "$WORK/sparse.toml" --scene "$SCENE" --frames 1 --out "$WORK/sparse-out" $option
done
[ ! -e "$WORK/sparse-out" ] && [ ! -e "$WORK/sparse-movie" ] && [ ! -e "$WORK/sparse.png" ] ||
    fail "render with a canvas beyond memory wrote output"
# With a rank per screen the worker accepts what the master refuses: still no rank makes the folder.
sed 's/screens_per_rank = 2/screens_per_rank = 1/' "$WORK/sparse.toml" > "$WORK/sparse-2-ranks.toml"
status=0
aw_mpirun 2 render --wall "$WORK/sparse-2-ranks.toml" --scene "$SCENE" --frames 1 --out "$WORK/sparse-out-2" \
    --gather > "$WORK/sparse-2.out" 2> "$WORK/sparse-2.err" || status=$?
[ "$status" = 1 ] || fail "2 ranks, a canvas beyond memory: exit $status, not 1"
grep -q "^aurorawall render: rank 0: --gather: the wall canvas of 1000001x1000001 pixels" "$WORK/sparse-2.err" ||
    fail "2 ranks, a canvas beyond memory: no message naming --gather: $(cat "$WORK/sparse-2.err")"
[ ! -e "$WORK/sparse-out-2" ] || fail "a worker made the --out folder of a run the master refused"
mkdir -p "$WORK/movie"
touch "$WORK/movie/frames.csv"
expect 1 "^aurorawall render: --movie .*/movie: already holds frames.csv of a movie; give another folder" \
    render --wall "$single" --scene "$SCENE" --frames 1 --movie "$WORK/movie"
[ "$(ls -A "$WORK/movie")" = frames.csv ] || fail "render --movie into an earlier movie wrote: $(ls -A "$WORK/movie")"
head -c 600 /dev/zero | tr '\0' a > "$WORK/long-token"
chmod 600 "$WORK/long-token"
expect 1 "^aurorawall render: .*long-token:1: --control-token-file: the secret is 600 bytes long, more than 512" \
    render --wall "$single" --scene "$SCENE" --frames 1 --control-port 0 --control-token-file "$WORK/long-token"
for args in "--help" "--wall $single --scene $SCENE --print-ranks"; do
    rc=0
    # shellcheck disable=SC2086 # the words of $args are the options
    "$AW" render $args >/dev/full 2>"$WORK/err" || rc=$?
    [ $rc = 1 ] && [ "$(grep -c '' "$WORK/err")" = 1 ] && grep -q "^aurorawall render: cannot write the output" "$WORK/err" ||
        fail "aurorawall render $args >/dev/full: exit status $rc, expected 1 with one error line: $(cat "$WORK/err")"
    echo "ok   1  aurorawall render $args >/dev/full: $(cat "$WORK/err")"
done

# airmass
expect 0 "--method" airmass --help
expect 2 "^aurorawall airmass: unrecognised option '--bogus'" airmass --bogus
expect 2 "^aurorawall airmass: --method: unknown value 'nope' \(allowed: list, exact, .*\)" airmass --method nope
printf '0,6371,0,0,1,0,0,100,8,6371\n1,2,3\n' >"$WORK/bad-rays.csv"
STDIN="$WORK/bad-rays.csv" expect 1 "^aurorawall airmass: line 2: " airmass
STDIN="$WORK" expect 1 "^aurorawall airmass: cannot read standard input" airmass

# tables
expect 0 "--energy-kev" tables --help
expect 2 "^aurorawall tables: unrecognised option '--bogus'" tables deposition --energy-kev 5 --bogus
expect 2 "^aurorawall tables: unknown table 'ozone' \(allowed: deposition, glory\)" tables ozone --energy-kev 5
expect 2 "^aurorawall tables: glory takes --scene FILE and nothing else" tables glory --energy-kev 5
expect 2 "^aurorawall tables: deposition takes --energy-kev E" tables deposition
expect 1 "^aurorawall tables: .*no-such-scene.toml" tables glory --scene "$WORK/no-such-scene.toml"
rc=0
"$AW" tables deposition --energy-kev 5 >/dev/full 2>"$WORK/err" || rc=$?
[ $rc = 1 ] && [ "$(grep -c '' "$WORK/err")" = 1 ] && grep -q "^aurorawall tables: " "$WORK/err" ||
    fail "aurorawall tables >/dev/full: exit status $rc, expected 1 with one error line: $(cat "$WORK/err")"
echo "ok   1  aurorawall tables deposition --energy-kev 5 >/dev/full: $(cat "$WORK/err")"

# accuracy: one parser for --airmass, --sky and --scene.
expect 0 "--scene" accuracy --help
expect 2 "^aurorawall accuracy: unrecognised option '--bogus'" accuracy --bogus
expect 2 "^aurorawall tables: unexpected argument 'junk'" tables deposition --energy-kev 5 junk
AURORAWALL_EGL_DEVICE=abc expect 1 "^aurorawall accuracy: EGL: AURORAWALL_EGL_DEVICE=abc is not a device number" \
    accuracy --sky --light-steps 1
expect 2 "^aurorawall render: unexpected argument 'extra'" render --scene "$SCENE" extra
expect 2 "^aurorawall accuracy: choose --airmass, --sky, --scene FILE or --glory FILE" accuracy
expect 2 "^aurorawall accuracy: --glory cannot be combined with --scene" accuracy --glory "$SCENE" --scene "$SCENE"
expect 1 "^aurorawall accuracy: .*does not list glory" accuracy --glory "$SCENE"
expect 1 "^aurorawall accuracy: .*airglow-limb.toml: the scene does not list aurora" \
    accuracy --scene "$SRC_DIR/config/scenes/airglow-limb.toml" --size 32x18
expect 2 "^aurorawall accuracy: --threads must be at most 1024" accuracy --scene "$SCENE" --threads 100000
expect 2 "^aurorawall accuracy: --size 99999x99999: more than 16777216 pixels" accuracy --scene "$SCENE" --size 99999x99999
expect 1 "^aurorawall accuracy: --size 100000x1: larger than this GL device's largest render target" \
    accuracy --scene "$SCENE" --size 100000x1
expect 2 "^aurorawall accuracy: --view-steps and --light-steps must be at most 4096" accuracy --sky --light-steps 1000000000
expect 2 "^aurorawall accuracy: --seed must be a whole number >= 0" accuracy --scene "$SCENE" --views 1 --seed -1
expect 2 "^aurorawall accuracy: --repeat applies to --airmass and --sky only" accuracy --scene "$SCENE" --repeat 4
expect 1 "^aurorawall accuracy: .*nonexistent-scene\.toml" accuracy --scene "$WORK/nonexistent-scene.toml"

# mie: exact Mie scattering by one sphere.
grep -Eq "^ +mie " <<<"$top" || fail "aurorawall --help does not list the command 'mie'"
expect 0 "--angles-deg" mie --help
expect 2 "^aurorawall render: --control-bind 0.0.0.0 opens the control port beyond this machine: it needs --control-token-file" render --wall "$WALLS/single.toml" --scene "$SCENE" --control-port 0 --control-bind 0.0.0.0
expect 2 "^aurorawall render: --control-bind notanip: not an IPv4 address" render --wall "$WALLS/single.toml" --scene "$SCENE" --control-port 0 --control-bind notanip
expect 2 "^aurorawall render: --control-token-file needs --control-port" render --wall "$WALLS/single.toml" --scene "$SCENE" --control-token-file /nonexistent
expect 2 "^aurorawall mie: unrecognised option '--bogus'" mie --n 1.33 --k 0 --x 1 --bogus
expect 2 "^aurorawall mie: --x must be in \[0.0001, " mie --n 1.33 --k 0 --x 0
expect 2 "^aurorawall mie: --x must be in \[0.0001, 100000\] \(got 1e-160\)" mie --n 1.33 --k 0 --x 1e-160
expect 2 "^aurorawall mie: --n must be in \[1, " mie --n 0.5 --k 0 --x 1
expect 2 "^aurorawall mie: --k must be in \[0, " mie --n 1.33 --k -1 --x 1
expect 2 "^aurorawall mie: --n must be in .*got nan" mie --n nan --k 0 --x 1
expect 2 "^aurorawall mie: .*'--x' is missing" mie --n 1.33 --k 0 --x
expect 2 "^aurorawall mie: --angles-deg: 'a' is not an angle" mie --n 1.33 --k 0 --x 1 --angles-deg 0,a
expect 2 "^aurorawall mie: --angles-deg: '0x10' is not an angle" mie --n 1.33 --k 0 --x 1 --angles-deg 0x10
"$AW" mie --n 1.5 --k 0 --x 10 --angles-deg 0,180 >"$WORK/mie.csv" || fail "aurorawall mie: exit status $?"
# Wiscombe (1979) tabulates Qext = 2.881999 to 7 digits: the printed value within half its last digit.
[ "$(sed -n 1p "$WORK/mie.csv" | cut -d, -f5)" = qext ] &&
    awk -v q="$(sed -n 2p "$WORK/mie.csv" | cut -d, -f5)" 'BEGIN { d = q - 2.881999; exit !(q != "" && d <= 0.5e-6 && d >= -0.5e-6) }' ||
    fail "aurorawall mie --n 1.5 --k 0 --x 10: Qext is not Wiscombe's 2.881999: $(cat "$WORK/mie.csv")"
echo "ok   0  aurorawall mie --n 1.5 --k 0 --x 10: Qext $(sed -n 2p "$WORK/mie.csv" | cut -d, -f5)"

# plasma: the action, the case and the leapfrog's stability limit.
expect 0 "--wp-dt" plasma --help
expect 2 "^aurorawall plasma: unrecognised option '--bogus'" plasma verify --bogus
expect 2 "^aurorawall plasma: missing the action \(allowed: verify, soak, accuracy\)" plasma
expect 2 "^aurorawall plasma: unknown action 'run' \(allowed: verify, soak, accuracy\)" plasma run
expect 2 "^aurorawall plasma: --case: unknown value 'ion-acoustic' \(allowed: all, langmuir, langmuir-2d, langmuir-3d, .*landau, diocotron\)" \
    plasma verify --case ion-acoustic
expect 2 "^aurorawall plasma: --wp-dt must be in \[0.01, 2\): the leapfrog is unstable" plasma verify --wp-dt 2
expect 2 "^aurorawall plasma: --wp-dt must be in \[0.01, 2\)" plasma verify --wp-dt 1e-300
expect 2 "^aurorawall plasma: --wc-dt must be in \[1e-06, 1000000\]" plasma verify --case boris --wc-dt 0
expect 2 "^aurorawall plasma: .*--wp-dt" plasma verify --wp-dt fast
expect 0 "--dx-lambda-d" plasma --help
expect 2 "^aurorawall plasma: --dx-lambda-d must be in \[0.01, 100\]" plasma verify --case heating --dx-lambda-d 0
expect 2 "^aurorawall plasma: .*--dx-lambda-d" plasma verify --case heating --dx-lambda-d wide
expect 0 "--device" plasma --help
expect 2 "^aurorawall plasma: --device: unknown value 'tpu' \(allowed: cpu, gpu\)" plasma verify --device tpu
expect 0 "--device gpu runs every case" plasma --help
expect 0 "langmuir-3d" plasma --help
expect 0 "--solver" plasma --help
expect 2 "^aurorawall plasma: --solver: unknown value 'fft' \(allowed: fft-cpu, jacobi, sor, multigrid\)" \
    plasma verify --device gpu --solver fft
expect 2 "^aurorawall plasma: --solver applies only to --device gpu" plasma verify --case boris --solver sor
expect 0 "--shape" plasma --help
expect 2 "^aurorawall plasma: --k-lambda-d must be in \[0.35, 0.7\] \(got 0.2\)" plasma verify --case landau --k-lambda-d 0.2
expect 2 "^aurorawall plasma: --k-lambda-d applies only to --case landau" plasma verify --case boris --k-lambda-d 0.4
expect 2 "^aurorawall plasma: --dx-lambda-d applies only to --case heating" plasma verify --case boris --dx-lambda-d 2
expect 2 "^aurorawall plasma: --shape: unknown value 'ngp' \(allowed: cic, tsc\)" plasma verify --case heating --shape ngp
expect 2 "^aurorawall plasma: --shape applies only to --case heating" plasma verify --case landau --shape tsc
# plasma verify --history: a folder that is not there is a runtime failure before any case runs; into
# one that is, two-stream writes two-stream.csv (the fit's numbers, then the table) and nothing else.
expect 0 "--history DIR" plasma --help
expect 1 "^aurorawall plasma: --history: '.*/no-such-folder' is not a directory" \
    plasma verify --case two-stream --history "$WORK/no-such-folder"
mkdir -p "$WORK/history"
"$AW" plasma verify --case two-stream --history "$WORK/history" >"$WORK/out" || fail "plasma verify --history: exit status $?"
[ "$(ls "$WORK/history")" = two-stream.csv ] || fail "plasma verify --history wrote: $(ls "$WORK/history")"
grep -q "^# fitted_rate = 0.3535" "$WORK/history/two-stream.csv" &&
    grep -q "^t_wp,field_mode_V_per_m,in_fit,fitted,expected$" "$WORK/history/two-stream.csv" ||
    fail "plasma verify --history: two-stream.csv lacks the fitted rate or the columns"
echo "ok   0  aurorawall plasma verify --case two-stream --history DIR: two-stream.csv"
# plasma soak and plasma accuracy: their options.
expect 0 "--every" plasma soak --help
expect 2 "^aurorawall plasma soak: the option '--scene' is required but missing" plasma soak
expect 2 "^aurorawall plasma soak: --steps must be >= 1" plasma soak --scene "$SRC_DIR/config/scenes/plasma-curls.toml" --steps 0
expect 1 "^aurorawall plasma soak: .*config/scenes/quiet-arc.toml: the scene does not list plasma" \
    plasma soak --scene "$SRC_DIR/config/scenes/quiet-arc.toml" --steps 1
expect 1 "^aurorawall plasma soak: .*missing.toml" plasma soak --scene missing.toml
expect 2 "^aurorawall plasma soak: --device: unknown value 'tpu' \(allowed: cpu, gpu\)" \
    plasma soak --scene "$SRC_DIR/config/scenes/plasma-curls.toml" --device tpu
expect 0 "--table" plasma accuracy --help
expect 2 "^aurorawall plasma accuracy: --table: unknown value 'noise' \(allowed: all, particles, time-step, solvers, heating\)" \
    plasma accuracy --table noise
echo "PASS help"
