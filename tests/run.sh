#!/bin/sh
# tests/run.sh TEST...: runs the cmocka unit test programs given, then every
# tests/*.sh script (end-to-end tests of the real binary, $SPRINGSIM), and prints one
# closing line "N passed, M failed" over all of them. Exits non-zero if anything failed.
#
# The tests are independent of one another (each script has its own scratch directory and
# its own tmux server), so they run J at a time (default: the number of processors, at
# least 2) with GNU parallel, the longest first (as long as each took last time, kept in
# $BUILD/test-times; before a first run, tests/lib/times: the seconds of each on a busy
# 2-core machine, for the order only); each one's output is shown whole when it ends.
# J=1 runs them one after the other, in name order.
#
# T (or TESTS): only the tests named, separated by blanks or commas: a script by its name
# (tui-ghost, tui-ghost.sh or tests/tui-ghost.sh), a unit test by its program's name
# (test_app). `make check T="tui-ghost plain"`.
#
# tests/run.sh --job DIR NAME: one test (used by the above), a script (NAME.sh, run by sh)
# or a program: its output into DIR/NAME.log, its exit status into DIR/NAME.rc, its
# seconds into DIR/NAME.time (NAME's slashes made _), then the output shown under
# "== NAME".
if [ "$1" = --job ]; then
    name=$3
    f=$2/$(echo "$name" | tr / _)
    case $name in *.sh) set -- sh "$name" ;; *) set -- "$name" ;; esac
    start=$(date +%s.%N)
    if "$@" >"$f.log" 2>&1 </dev/null; then echo 0 >"$f.rc"; else echo $? >"$f.rc"; fi
    secs=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
    echo "$secs" >"$f.time"
    echo "== $name ($secs s)"
    cat "$f.log"
    exit 0
fi

work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
times=${BUILD:-build}/test-times
want=$(echo "${T:-$TESTS}" | tr ',' ' ')

# chosen NAME: NAME is among the tests asked for (all of them if none were named)
chosen() {
    [ -z "$want" ] && return 0
    c_base=${1##*/}
    for w in $want; do
        w=${w##*/}
        case $w in "$c_base" | "${c_base%.sh}" | "${c_base%.sh}.sh") return 0 ;; esac
    done
    false
}

# The jobs, one a line: the unit test programs, then the scripts.
for t in "$@"; do
    chosen "$t" && echo "$t"
done >"$work/jobs"
for s in tests/*.sh; do
    [ "$s" = tests/run.sh ] || ! chosen "$s" || echo "$s"
done >>"$work/jobs"
for w in $want; do
    w=${w##*/}
    if ! sed 's,.*/,,; s,\.sh$,,' "$work/jobs" | grep -qx -- "${w%.sh}"; then
        echo "run.sh: T: no test is named '$w' (allowed: a script of tests/ with or without .sh, or a unit test program's name such as test_app)" >&2
        exit 2
    fi
done

if [ -z "$J" ]; then
    J=$(nproc 2>/dev/null || echo 2)
    [ "$J" -ge 2 ] || J=2
fi
case $J in '' | *[!0-9]* | 0)
    echo "run.sh: J=$J: the number of tests to run at a time, 1 or more" >&2
    exit 2
    ;;
esac
if [ "$J" -gt 1 ] && ! command -v parallel >/dev/null 2>&1; then
    echo "run.sh: GNU parallel is not installed (mk/deps.sh test): the tests run one at a time"
    J=1
fi

mkdir -p "$work/out"
if [ "$J" -eq 1 ]; then
    while read -r name; do
        sh tests/run.sh --job "$work/out" "$name"
    done <"$work/jobs"
else
    # the longest first: last time's seconds (an unknown test counts as long)
    # (a test known by its file's name: test_app, tui-ghost.sh)
    cat "$times" tests/lib/times >"$work/last" 2>/dev/null
    awk -F '\t' '{ k = $1; sub(/.*\//, "", k) }
                 FILENAME != ARGV[2] { if (!(k in s)) s[k] = $2; next }
                 { printf "%s\t%s\n", (k in s ? s[k] : 1e6), $0 }' \
        "$work/last" "$work/jobs" | sort -t '	' -k 1,1 -g -r | cut -f 2- >"$work/order"
    echo "run.sh: $(wc -l <"$work/order" | tr -d ' ') tests, $J at a time"
    parallel --will-cite -j "$J" --group sh tests/run.sh --job "$work/out" {} <"$work/order"
fi

# The counts: "N passed, M failed" lines of the scripts, cmocka's [ PASSED ] / [ FAILED ]
# lines; a non-zero exit with no failure counted still counts as one failure.
passed=0
failed=0
while read -r name; do
    o=$work/out/$(echo "$name" | tr / _)
    log=$o.log
    [ -f "$log" ] || { echo "$name did not run"; failed=$((failed + 1)); continue; }
    p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p; s/^.*: \([0-9]*\) passed, [0-9]* failed.*/\1/p' "$log" | awk '{s+=$1} END {print s+0}')
    f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p; s/^.*: [0-9]* passed, \([0-9]*\) failed.*/\1/p' "$log" | awk '{s+=$1} END {print s+0}')
    passed=$((passed + p))
    failed=$((failed + f))
    status=$(cat "$o.rc" 2>/dev/null || echo 1)
    if [ "$status" -ne 0 ] && [ "$f" -eq 0 ]; then
        echo "$name exited with status $status"
        failed=$((failed + 1))
    fi
    if [ "$status" -ne 0 ] || [ "$f" -gt 0 ]; then
        echo "$name" >>"$work/failed"
    fi
    printf '%s\t%s\n' "$name" "$(cat "$o.time")" >>"$work/times"
done <"$work/jobs"
# this run's seconds kept for the next one's order (those not run keep their old figure)
if [ -d "$(dirname "$times")" ]; then
    { cat "$work/times"; cat "$times" 2>/dev/null; } | awk -F '\t' '!seen[$1]++' >"$times.tmp" &&
        mv -f "$times.tmp" "$times"
fi

# What failed, again at the end (a log's tail is often all one reads): each test's name
# and its first failure lines.
if [ -s "$work/failed" ]; then
    echo
    while read -r name; do
        echo "failed: $name"
        grep -E '^(FAIL|not ok)|\[  (FAILED|ERROR)  *\]|ERROR|error:' \
            "$work/out/$(echo "$name" | tr / _).log" | head -n 5 | cut -c 1-300 | sed 's/^/    /'
    done <"$work/failed"
fi
echo
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
