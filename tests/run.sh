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

for t in "$@"; do
    echo "== $t"
    if "$t" >"$log" 2>&1; then status=0; else status=$?; fi
    cat "$log"
    count
    if [ "$status" -ne 0 ] && ! grep -q '^\[  FAILED  \]' "$log"; then
        echo "$t exited with status $status"
        failed=$((failed + 1))
    fi
done

for s in tests/*.sh; do
    [ "$s" = tests/run.sh ] && continue
    echo "== $s"
    if sh "$s" >"$log" 2>&1; then status=0; else status=$?; fi
    cat "$log"
    count
    if [ "$status" -ne 0 ] && ! grep -q ' passed, [0-9]* failed' "$log"; then
        echo "$s exited with status $status"
        failed=$((failed + 1))
    fi
done

echo
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
