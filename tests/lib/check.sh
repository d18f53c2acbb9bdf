# tests/lib/check.sh: what the shell test scripts share. Source it after setting NAME:
# it makes $SPRINGSIM absolute, a scratch directory $tmp removed at exit, pass and fail,
# summary, which prints "NAME: N passed, M failed" and gives the exit status,
# plain_env, which keeps the user's presets and lessons out of the way (an empty user directory,
# no $SPRINGSIM_PRESETS or $SPRINGSIM_LESSONS) in the C locale, and run, one run of the binary.
SPRINGSIM=${SPRINGSIM:-./springsim}
case $SPRINGSIM in /*) ;; */*) SPRINGSIM=$PWD/$SPRINGSIM ;; esac
passed=0
failed=0
tmp=$(mktemp -d) || exit 1
cleanup() { rm -rf "$tmp"; }
trap 'cleanup' EXIT
pass() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); printf 'FAIL: %s\n' "$*"; }
summary() {
    echo "$NAME: $passed passed, $failed failed"
    [ "$failed" -eq 0 ]
}
plain_env() {
    mkdir -p "$tmp/xdg"
    XDG_CONFIG_HOME=$tmp/xdg
    export XDG_CONFIG_HOME
    unset SPRINGSIM_PRESETS SPRINGSIM_LESSONS
    LC_ALL=C
    export LC_ALL
}

# run ARGS...: the binary (a minute at most); stdout in $out, stderr in $err, the exit
# status in $rc, and the command as written in $cmd for messages.
out=$tmp/stdout
err=$tmp/stderr
run() {
    cmd="springsim $*"
    timeout 60 "$SPRINGSIM" "$@" >"$out" 2>"$err"
    rc=$?
}
