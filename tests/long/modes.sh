#!/bin/sh
# tests/long/modes.sh: --modes on the half-damped chain (the left half's masses damped by
# 2 N s/m, the right half's not, walls at both ends, springs of 10 N/m) at N = 1000: the
# damped eigenproblem of its 2000 states in under 60 s of processor time, every mode
# given a frequency and, paired or overdamped, a damping ratio. (N = 300, under 2 s, is
# in tests/cli.sh; the ratios' accuracy at N = 101 in test_damped.) Ends "modes-long:
# N passed, M failed".
NAME=modes-long
. "$(dirname "$0")/../lib/check.sh"

n=1000
d=$(awk -v n=$n 'BEGIN { for (i = 1; i <= n; i++) printf "%s%s", (i > 1 ? "," : ""), (i <= n / 2 ? 2 : 0) }')
/usr/bin/time -f '%U %S' -o "$tmp/time" "$SPRINGSIM" --modes -n $n --spring 10 --boundary wall \
    --damping "$d" >"$tmp/out.csv" 2>"$tmp/err"
rc=$?
secs=$(tail -n 1 "$tmp/time" | awk '{ print $1 + $2 }')
rows=$(awk -F, 'NR > 1 && $2 > 0 && $4 != "" { k++ } END { print k + 0 }' "$tmp/out.csv")
if [ "$rc" -eq 0 ] && [ "$rows" -eq $n ] && awk -v s="$secs" 'BEGIN { exit !(s > 0 && s < 60) }'; then
    pass
else
    fail "--modes -n $n half-damped: expected exit 0, $n modes with a ratio, under 60 s; exit $rc, $rows modes, $secs s: $(head -c 300 "$tmp/err")"
fi
echo "modes $n: $secs s of processor time"
summary
