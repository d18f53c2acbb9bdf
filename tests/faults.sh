#!/bin/sh
# tests/faults.sh: quick fault tests of the real binary ($SPRINGSIM): killed mid-write,
# huge and malformed presets, no HOME, closed output, and the stability warning.
# Ends with "faults: N passed, M failed". The long ones live in tests/long/.
NAME=faults
. "$(dirname "$0")/lib/check.sh"
XDG_CONFIG_HOME=$tmp/xdg
export XDG_CONFIG_HOME
unset SPRINGSIM_PRESETS

# 1. kill -9 in the middle of a long --headless -o FILE: FILE keeps its old content and
# no temporary file is left beside it.
printf 'old content\n' >"$tmp/out.csv"
"$SPRINGSIM" --headless -n 200 --duration 100000 -o "$tmp/out.csv" 2>/dev/null &
pid=$!
sleep 0.5
if kill -0 "$pid" 2>/dev/null; then
    kill -9 "$pid"
    wait "$pid" 2>/dev/null
    if [ "$(cat "$tmp/out.csv")" = "old content" ]; then pass; else
        fail "kill -9 during -o: the old file changed: $(head -c 80 "$tmp/out.csv")"
    fi
    left=$(ls "$tmp" | grep -c 'out.csv.tmp' || true)
    if [ "$left" -eq 0 ]; then pass; else fail "kill -9 during -o left $left temporary files"; fi
else
    fail "the long run ended before it could be killed"
fi
# ...and a run that completes replaces it whole.
"$SPRINGSIM" --headless --duration 1 -o "$tmp/out.csv" && [ "$(wc -l <"$tmp/out.csv")" -eq 102 ] &&
    pass || fail "a complete run did not replace the file with 102 lines"

# one_line STATUS NEEDLE ARGS...: exit STATUS, one stderr line containing NEEDLE.
one_line() {
    want=$1 needle=$2
    shift 2
    "$SPRINGSIM" "$@" >"$tmp/o" 2>"$tmp/e"
    rc=$?
    n=$(awk 'END { print NR }' "$tmp/e")
    if [ "$rc" -eq "$want" ] && [ "$n" -eq 1 ] && grep -q -- "$needle" "$tmp/e"; then pass; else
        fail "springsim $*: expected exit $want and one line with '$needle'; got exit $rc, $n lines: $(head -c 200 "$tmp/e")"
    fi
}

# 2. A 1 MB preset, a 100,000-character line, binary junk.
awk 'BEGIN { print "[system]"; for (i = 0; i < 40000; i++) print "; padding padding padding" }' \
    >"$tmp/big.ini"
one_line 2 "too large" -p "$tmp/big.ini" --modes
awk 'BEGIN { printf "[system]\nmass = "; for (i = 0; i < 50000; i++) printf "1,"; print "1" }' \
    >"$tmp/long.ini"
one_line 2 "long.ini:2: line is longer than" -p "$tmp/long.ini" --modes
head -c 4096 /dev/urandom >"$tmp/junk.ini"
"$SPRINGSIM" -p "$tmp/junk.ini" --modes >/dev/null 2>"$tmp/e"
rc=$?
if [ "$rc" -eq 2 ] && [ "$(awk 'END { print NR }' "$tmp/e")" -eq 1 ]; then pass; else
    fail "random bytes as a preset: expected exit 2 and one line, got exit $rc: $(head -c 200 "$tmp/e")"
fi
one_line 1 "No such file or directory" -p "$tmp/missing.ini" --modes
one_line 1 "Is a directory" -p "$tmp/" --modes
if [ "$(id -u)" -ne 0 ]; then
    printf '[system]\nmasses = 2\n' >"$tmp/locked.ini"
    chmod 000 "$tmp/locked.ini"
    one_line 1 "Permission denied" -p "$tmp/locked.ini" --modes
else
    echo "note: running as root, so an unreadable preset cannot be made; not tested"
fi

# 3. No HOME and no XDG_CONFIG_HOME: presets beside the binary still work.
out=$(env -u HOME -u XDG_CONFIG_HOME "$SPRINGSIM" -p resonance --modes 2>&1)
case $out in *0.711762*) pass ;; *) fail "no HOME: -p resonance --modes gave: $out" ;; esac
n=$(env -u HOME -u XDG_CONFIG_HOME "$SPRINGSIM" --list-presets 2>/dev/null | grep -c .)
if [ "$n" -ge 11 ]; then pass; else fail "no HOME: --list-presets listed $n presets"; fi

# 4. Output that cannot be written: a closed standard output, a full device.
"$SPRINGSIM" --headless --duration 1 >&- 2>"$tmp/e"
rc=$?
if [ "$rc" -eq 1 ] && [ "$(awk 'END { print NR }' "$tmp/e")" -eq 1 ]; then pass; else
    fail "closed stdout: expected exit 1 and one line, got $rc: $(head -c 200 "$tmp/e")"
fi
one_line 1 "No space left on device" --headless --duration 100 -o /dev/full

# 5. A step past the stability limit is warned about before anything blows up, and a
# run that blows up stops with the limit named, never printing nan.
"$SPRINGSIM" --headless --spring 5000 --dt 0.05 --duration 5 >"$tmp/o" 2>"$tmp/e"
rc=$?
if [ "$rc" -eq 1 ] && grep -q 'warning: dt = 0.05 s is unstable with rk4 for these springs and dampers' "$tmp/e" &&
    grep -q 'dt < 0.0' "$tmp/e" && ! grep -qi nan "$tmp/o"; then pass; else
    fail "unstable dt: expected a warning, a stop naming the limit and no nan; got $rc: $(head -c 300 "$tmp/e")"
fi
# In a terminal (tests/lib/tmux.sh; skipped without tmux): the same warning and stop.
if command -v tmux >/dev/null 2>&1; then
    f_lc=${LC_ALL-}
    . "$(dirname "$0")/lib/tmux.sh"
    start unstable 100 30 -- --spring 5000 --dt 0.05
    start sel 120 40 -- -n 10
    start lowbw 120 40 -- --low-bandwidth
    S=unstable
    if wait_for 'above the stability limit' 3; then pass; else
        fail "interactive: no stability warning at start with dt 0.05 and k 5000; bottom line: $(last_line)"
    fi
    keys Space
    if wait_all 3 "has 'unstable with rk4: dt < 0.0' && has 's is stable' && has Paused"; then
        pass
    else
        fail "interactive: running an unstable chain did not pause with the limit; bottom line: $(last_line)"
    fi
    if grep -qiE '(^|[^[:alpha:]])[-+]?(nan|inf)([^[:alpha:]]|$)' "$scr"; then fail "interactive: nan or inf on screen"; else pass; fi
    # Found in review: with spring 10 of a 10-mass chain selected, loading a one-mass
    # preset kept the selection past the end of the chain (an out-of-bounds read).
    if up sel; then
        keys Tab
        wait_for '─ mass 1: m' 3
        keys Up
        # springs numbered from 1 as in --spring, with what they join (issue 22, item 9)
        if wait_for '─ spring 1 (wall–1): k' 3; then pass; else
            fail "Tab, ↑ should select spring 1 (wall–1), the first of --spring; screen: $(brief "$scr" '^└─ ')"
        fi
        keys Up
        if wait_for '─ spring 11 (10–motor): k' 3; then
            keys p
            wait_for ' Presets ' 3
            keys Down Enter
            wait_gone ' Presets ' 3
            if has 'EXITED'; then fail "loading a shorter preset with the chain focused killed the program"
            elif has 'spring 11'; then fail "the selection stayed on spring 11 of a one-mass chain"
            elif wait_for '─ mass 1: m' 3 && wait_for 'N 1 ' 3; then pass
            else fail "after loading a shorter preset the chain selection is not on mass 1: $(grep '^└─ ' "$scr" | head -n 1)"
            fi
        else
            fail "Tab, ↑, ↑ on a 10-mass chain should select spring 11 (10–motor); screen: $(brief "$scr" '^└─ ')"
        fi
    fi
    # --low-bandwidth shows in the status line and on its control, which turns it off.
    if up lowbw; then
        # named Refresh, not Bandwidth, beside the modes' −3 dB bandwidth (issue 22, item 6)
        if has 'low refresh' && has 'Refresh    low (slow link)' && ! has 'Bandwidth'; then pass; else
            fail "--low-bandwidth: not shown in the status ('low refresh') and the Refresh control ('low (slow link)'); screen: $(brief "$scr" 'Refresh|Bandwidth')"
        fi
        keys Up Up Right # Graphics is the last control, Refresh the one above it
        if wait_for 'Refresh    normal' 3; then pass; else fail "the Refresh control did not turn the low refresh off"; fi
    fi
    tm kill-server 2>/dev/null
    if [ -n "$f_lc" ]; then LC_ALL=$f_lc; else unset LC_ALL; fi
fi

# 6. A terminal that stops reading (a stalled link): the program steps down to low
# bandwidth on its own and says so (tests/slowterm.c, built by make check).
if [ -x "${SLOWTERM:-}" ]; then
    out=$("$SLOWTERM" "$SPRINGSIM")
    case $out in *"slowterm: "*" 0 failed"*) pass ;; *) fail "slow terminal: $out" ;; esac
else
    echo "note: SLOWTERM not built; the stalled-terminal test did not run"
fi

summary
