#!/bin/bash
# The launch scripts' command-line convention: each answers --help with its usage on stdout and status
# 0 and does nothing else; an option given without its value is one line naming it and status 2;
# gpu-bundle never replaces a folder or file that is not an earlier bundle. Nothing here renders.
source "$(dirname "$0")/lib.sh"
launch="$SRC_DIR/launch"

for script in $(cd "$launch" && find . -type f -perm -u+x ! -name '*.py' | sed 's|^\./||' | sort); do
    code=0
    timeout 30 "$launch/$script" --help >"$WORK/out" 2>"$WORK/err" || code=$?
    [ $code = 0 ] || fail "launch/$script --help: status $code: $(head -c 300 "$WORK/err")"
    [ -s "$WORK/out" ] || fail "launch/$script --help printed nothing on stdout"
done
note "every launch script answers --help"

# SCRIPT [ARGS...] OPTION: the option last, without its value.
for call in "gpu-check --out" "benchmark-path --size" "work-stats --view-size" "march-stages --csv" \
            "accuracy-views --views" "beside-2011 --runs" "llvmpipe-instructions --time" "scaling --ranks" \
            "cpu-noise --frames" "control-flood-bench --wall" "gpu-bundle $WORK/bundle --build"; do
    read -ra words <<<"$call"
    option=${words[-1]}
    code=0
    timeout 30 "$launch/${words[0]}" "${words[@]:1}" >"$WORK/out" 2>"$WORK/err" || code=$?
    [ $code = 2 ] || fail "launch/$call: status $code, not 2: $(head -c 300 "$WORK/err")"
    [ "$(wc -l <"$WORK/err")" = 1 ] && grep -q -- "$option needs a value" "$WORK/err" ||
        fail "launch/$call: not one line naming $option: $(head -c 300 "$WORK/err")"
done
note "an option without its value: one line naming it, status 2"

code=0
timeout 30 "$launch/wall-control" --port 70000 status 2>"$WORK/err" || code=$?
[ $code = 2 ] && grep -q -- "--port must be in 1..65535" "$WORK/err" || fail "wall-control --port 70000: status $code"

# gpu-bundle replaces only an earlier bundle: a folder of something else, and a file, are left whole.
mkdir "$WORK/other" && echo keep >"$WORK/other/file" && echo keep >"$WORK/plain"
for dest in "$WORK/other" "$WORK/plain"; do
    code=0
    timeout 60 "$launch/gpu-bundle" "$dest" --build "$BUILD_DIR" >"$WORK/out" 2>"$WORK/err" || code=$?
    [ $code = 1 ] && grep -q "is not an earlier bundle" "$WORK/err" ||
        fail "gpu-bundle $dest: status $code: $(head -c 300 "$WORK/err")"
done
[ "$(cat "$WORK/other/file")" = keep ] && [ "$(cat "$WORK/plain")" = keep ] || fail "gpu-bundle touched what it refused"
echo "PASS launch_options"
