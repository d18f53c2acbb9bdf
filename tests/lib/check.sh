# tests/lib/check.sh: what the shell test scripts share. Source it after setting NAME:
# it makes $SPRINGSIM absolute, a scratch directory $tmp removed at exit, pass and fail,
# summary, which prints "NAME: N passed, M failed" and gives the exit status, plain_env,
# which keeps the user's presets and lessons out of the way (an empty user directory, no
# $SPRINGSIM_PRESETS or $SPRINGSIM_LESSONS) in the C locale, run, one run of the binary,
# and refused and accepted (a run refused with exit 2 and one clean line, or accepted
# without a word).
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

# show FILE: its first 300 bytes on one line, for a message (a script may redefine it, e.g.
# as od -c to make control bytes visible).
show() { head -c 300 "$1" | tr '\n' '|'; }

# refused NEEDLE ARGS...: exit 2, exactly one line on stderr that holds NEEDLE and no
# control byte, nothing on stdout.
refused() {
    needle=$1
    shift
    run "$@"
    lines=$(awk 'END { print NR }' "$err")
    if [ "$rc" -ne 2 ] || [ -s "$out" ] || [ "$lines" -ne 1 ] ||
        ! grep -qF -- "$needle" "$err" || LC_ALL=C grep -q '[[:cntrl:]]' "$err"; then
        fail "$cmd: expected exit 2 and one clean line with '$needle', got exit $rc," \
            "$lines lines: $(show "$err")"
    else
        pass
    fi
}

# accepted ARGS...: exit 0, nothing on stderr.
accepted() {
    run "$@"
    if [ "$rc" -ne 0 ] || [ -s "$err" ]; then
        fail "$cmd: expected exit 0, got $rc: $(show "$err")"
    else
        pass
    fi
}
