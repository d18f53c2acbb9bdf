#!/bin/sh
# tests/harden-values.sh: hostile values on the command line (issue 11, defects 9, 10, 13,
# 14, 17 and 19): blanks in numbers, control bytes and huge values in messages, long list
# items, help-type output to a full disk, runs that could never finish, and the wording of
# a few messages. Run from the repository root as `sh tests/harden-values.sh`, with
# SPRINGSIM naming the binary (default ./springsim). Prints one line per failing case,
# then "harden-values: N passed, M failed".
NAME=harden-values
. "$(dirname "$0")/lib/check.sh"

plain_env

nl='
'
esc=$(printf '\033')
bel=$(printf '\007')
vt=$(printf '\013')


show() { head -c 300 "$1" | od -c | head -5 | tr '\n' '|'; }

# --- 9: one rule for blanks: none before, after or inside a number ---
refused "starts with a blank" --modes --dt " 0.01"
refused "starts with a blank" --modes --dt "${nl}0.01"
refused "starts with a blank" --modes --dt "${vt}0.01"
refused "is not a number" --modes --dt "0.01${nl}"
refused "is not a number" --modes --amplitude "1 "
refused "starts with a blank" --modes --mass " 1"
refused "is not a number" --modes --mass "1,${nl}2"
refused "--sweep" --sweep " 1:2:3"
refused "--sweep" --sweep "1:2: 3"
refused "--sweep" --sweep "1: 2:3"
refused "--sweep" --sweep "1:2:3 "
refused "--sweep" --sweep "1:2:${nl}3"
accepted --modes -n 3 --mass "1, 2 ,3"
accepted --sweep 1:2:3

# --- 10: control bytes escaped, long values cut, in every message ---
refused "'\\x1b]0;PWNED\\a'" --modes --dt "${esc}]0;PWNED${bel}"
refused "'0.0\\n1'" --modes --dt "0.0${nl}1"
refused "is not an option" "--x${esc}[2J"
long=$(head -c 131000 /dev/zero | tr '\0' x)
run "--$long"
if [ "$rc" -eq 2 ] && [ "$(wc -c <"$err")" -lt 300 ] && grep -q '\.\.\.' "$err"; then
    pass
else
    fail "a 131,000-character option: exit $rc, $(wc -c <"$err") bytes on stderr"
fi
refused "131" --modes --dt "0.$long"
mkdir -p "$tmp/presets"
printf '[preset]\ndescription = evil \033]0;PWNED\007 title\n[system]\nmasses = 1\n' \
    >"$tmp/presets/evil.ini"
SPRINGSIM_PRESETS=$tmp/presets "$SPRINGSIM" --list-presets >"$out" 2>"$err"
rc=$?
if [ "$rc" -eq 0 ] && grep -q 'evil' "$out" && grep -qF '\x1b]0;PWNED\a' "$out" &&
    ! grep -q "$esc" "$out"; then
    pass
else
    fail "--list-presets with a description holding ESC: exit $rc, $(show "$out")"
fi

# --- 13: a list item of any length is read as the number it is ---
zeros=$(head -c 70 /dev/zero | tr '\0' 0)
accepted --modes --mass "0.${zeros}1"
accepted --modes -n 2 --mass "1,0.${zeros}1"
refused "item 2" --modes --mass "1,0.${zeros}1x"

# --- 14: help-type output to a full disk ---
if [ -w /dev/full ]; then
    for opt in --version --help --keys --list-presets; do
        "$SPRINGSIM" "$opt" >/dev/full 2>"$err"
        rc=$?
        if [ "$rc" -eq 1 ] &&
            grep -qx 'springsim: standard output: No space left on device' "$err"; then
            pass
        else
            fail "springsim $opt >/dev/full: exit $rc, stderr: $(show "$err")"
        fi
    done
fi

# --- 17: runs that could never finish are refused before they start ---
refused "steps" --headless --duration 1e300 --sample 1e300
refused "steps" --headless --dt 1e-320
refused "steps" --headless --duration 1e11
accepted --headless --duration 0.05 --dt 1e-3
printf '[run]\nduration = 1e300\n' >"$tmp/long.ini"
refused "long.ini:2: duration" --headless -p "$tmp/long.ini"

# --- 19: messages ---
accepted --modes -n +3
refused "out of range" --modes -n -3
accepted --headless --duration 0 --seed +7 --random
run -- --dt
if [ "$rc" -eq 2 ] && grep -q "takes no arguments" "$err" && grep -q "'--dt'" "$err" &&
    ! grep -q "is not an option" "$err"; then
    pass
else
    fail "springsim -- --dt: exit $rc, $(show "$err")"
fi
refused "--random: takes no value" --random=maybe --modes
run --headless --duration 0.05 --mass 1e-300
if grep -q 'inf s' "$err"; then
    fail "springsim --headless --mass 1e-300: 'inf s' in $(show "$err")"
else
    pass
fi

# --- issue 31: an amplitude that leaves the blocks no room (A > L - N w) is refused ---
refused "'6.5' leaves the 20 blocks no room" --headless -n 20 --amplitude 6.5
refused "expected amplitude <= L - N w = 9.2 m" --headless -n 2 --wave square --amplitude 9.3
refused "leaves the 2 blocks no room" --headless -n 2 --preset square-wave --amplitude 9.21
# At the limit, with collisions off or no piston, the same amplitude runs.
for args in "-n 2 --amplitude 9.2" "-n 20 --amplitude 6.5 --no-collisions" \
    "-n 20 --amplitude 6.5 --boundary wall"; do
    # shellcheck disable=SC2086
    if "$SPRINGSIM" --headless $args --duration 0.1 >/dev/null 2>&1; then pass; else
        fail "--headless $args: refused (expected a run)"
    fi
done

# --- a warning is true or not said: the drive's error measured where its numbers have no
# digits left (dt = 1e-16 s: e^(i w dt) rounds to 1; a spring of 1e-320 N/m, subnormal,
# the drive's force too) said 'accurate only roughly... dt < 0.116 s keeps it under 1 %'
# of a dt far below that, and 'dt < 0 s' ---
accepted --headless --duration 0 --dt 1e-16
accepted --headless --duration 0 --dt 1e-100
accepted --headless --duration 0 --spring 1e-320
# and a real one is still said
run --headless --duration 0 --dt 0.01 --frequency 37.3
grep -q "accurate only roughly: the steady motion at the 37.3 Hz drive.*dt < 0.007" "$err" && pass ||
    fail "--dt 0.01 --frequency 37.3: expected the drive's accuracy warning; got: $(show "$err")"

summary
