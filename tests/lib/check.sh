# tests/lib/check.sh: what the shell test scripts share. Source it after setting NAME:
# it makes $SPRINGSIM absolute, a scratch directory $tmp removed at exit, pass and fail,
# and summary, which prints "NAME: N passed, M failed" and gives the exit status.
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
