#!/bin/sh
# tests/run.sh TEST...: runs the cmocka unit test programs given, then every
# tests/*.sh script (end-to-end tests of the real binary, $SPRINGSIM), and prints one
# closing line "N passed, M failed" over all of them. Exits non-zero if anything failed.
passed=0
failed=0
log=$(mktemp)
trap 'rm -f "$log"' EXIT

count() { # adds the "N passed, M failed" or cmocka lines of $log to the totals
    p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p; s/^.*: \([0-9]*\) passed, [0-9]* failed.*/\1/p' "$log" | awk '{s+=$1} END {print s+0}')
    f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p; s/^.*: [0-9]* passed, \([0-9]*\) failed.*/\1/p' "$log" | awk '{s+=$1} END {print s+0}')
    passed=$((passed + p))
    failed=$((failed + f))
}

# run_one NAME CMD...: runs one test program or script, shows its output, adds its
# counts; a non-zero exit with no failure counted still counts as one failure.
run_one() {
    name=$1
    shift
    echo "== $name"
    if "$@" >"$log" 2>&1; then status=0; else status=$?; fi
    cat "$log"
    before=$failed
    count
    if [ "$status" -ne 0 ] && [ "$failed" -eq "$before" ]; then
        echo "$name exited with status $status"
        failed=$((failed + 1))
    fi
}

for t in "$@"; do
    run_one "$t" "$t"
done
for s in tests/*.sh; do
    [ "$s" = tests/run.sh ] || run_one "$s" sh "$s"
done

echo
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
