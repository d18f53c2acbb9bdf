#!/bin/sh
# tests/harden-hostile.sh: the hostile round of issue 23 (items 2 and 4 to 13): initial
# states the model cannot hold, numbers kept to a width, limits kept on every path,
# wording, options that would be ignored, long output names, Unicode format characters
# and races between two instances. Run from the repository root as
# `sh tests/harden-hostile.sh`, with SPRINGSIM naming the binary (default ./springsim).
# Prints one line per failing case, then "harden-hostile: N passed, M failed".
NAME=harden-hostile
. "$(dirname "$0")/lib/check.sh"

plain_env

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

# no_inf_nan FILE WHAT: FILE holds no inf, nan and no number of more than 20 digits.
no_inf_nan() {
    if grep -qiE '(^|[^a-z])(-?inf|-?nan)([^a-z]|$)|[0-9]{21}' "$1"; then
        fail "$2: inf, nan or a huge number: $(grep -oiE '.{0,30}(inf|nan|[0-9]{21}).{0,10}' "$1" | head -2 | tr '\n' '|')"
    else
        pass
    fi
}

# --- 2: initial states bounded to what the model holds (walls 10 m apart, the cap) ---
refused "-10 <= displacements <= 10 m" --x0 1e160
refused "-10 <= displacements <= 10 m" --headless --energy --x0 1e154
refused "-10 <= displacements <= 10 m" --headless --x0 1.7e308
refused "'-10.5'" --modes -n 2 --x0 0,-10.5
refused "-50 <= velocities <= 50 m/s" --headless --v0 1e300
refused "0 <= AMP <= 10 m" --headless --start-mode 1:1e308
refused "0 <= AMP <= 10 m" --headless --start-mode 1:10.01
refused "-10 <= displacements <= 10 m" --plain --x0 1e300
printf '[initial]\nx0 = 1e300\n' >"$tmp/huge.ini"
refused "huge.ini:2: x0" --headless -p "$tmp/huge.ini"
accepted --headless --duration 0 --x0 10 --v0 -50 -n 1 --boundary wall
accepted --headless --duration 0.1 --start-mode 1:10
# A state inside the bounds whose energy still overflows (springs of 1e308 N/m): the run
# stops as a blow-up, and the CSV holds no row with inf or nan.
run --headless --energy --spring 1e308 --x0 1 --duration 0.05
if [ "$rc" -eq 1 ] && grep -q "blew up at t = 0 s" "$err"; then pass; else
    fail "$cmd: expected exit 1 and a blow-up at t = 0, got $rc: $(show "$err")"
fi
no_inf_nan "$out" "$cmd"
# --plain: the status line in a width whatever the values; Q of an undamped mode in words.
printf 'modes\nstatus\n' | "$SPRINGSIM" --plain -n 1 --spring 1e300 --damping 0 --x0 9 \
    >"$out" 2>&1
no_inf_nan "$out" "--plain --spring 1e300 --damping 0, modes"

# --- 13: --summary --meta on a run that blows up: no '#' lines alone ---
run --summary --meta --spring 1e308 --x0 1 --duration 0.05
if [ "$rc" -eq 1 ] && [ ! -s "$out" ]; then pass; else
    fail "$cmd: expected exit 1 and nothing on stdout, got $rc: $(show "$out")"
fi
run --summary --meta --duration 0.05
if [ "$rc" -eq 0 ] && [ "$(grep -c '^#' "$out")" -eq 2 ] &&
    [ "$(grep -vc '^#' "$out")" -eq 2 ]; then pass; else
    fail "$cmd: expected two '#' lines, a header and a row, got $rc: $(show "$out")"
fi

summary
