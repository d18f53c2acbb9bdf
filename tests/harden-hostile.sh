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
refused "0 <= amplitude <= 10" --headless --amplitude 11
refused "0 <= amplitude <= 10" --headless --amplitude 1e308
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

# A drive of 1e308 m made inf accelerations in the cursor's readout; a mode of 1e149 Hz
# was said in 150 digits when the chain started in it.
printf 'set amplitude 1e308\nset spring 1e300\nmode 1\nrun 0.5\ncursor 0.2\n' |
    timeout 60 "$SPRINGSIM" --plain -n 1 >"$out" 2>&1
no_inf_nan "$out" "--plain, amplitude 1e308, spring 1e300, mode 1, cursor"
if grep -q "^error amplitude: '1e308' is out of range" "$out" &&
    grep -q '^ok started in mode 1 (2\.251e+149 Hz)' "$out"; then pass; else
    fail "--plain, amplitude 1e308 and mode 1 at 2.251e+149 Hz: $(show "$out")"
fi

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

# plain CMDS ARGS...: the plain mode with the commands CMDS on standard input, its output
# in $out.
plain() {
    cmds=$1
    shift
    printf '%b' "$cmds" | timeout 60 "$SPRINGSIM" --plain "$@" >"$out" 2>"$err"
    rc=$?
}

# has WHAT PATTERN: the plain output holds a line matching PATTERN (grep -E).
has() {
    if grep -qE -- "$2" "$out"; then pass; else
        fail "$1: expected a line matching '$2', got: $(show "$out")"
    fi
}
hasnt() {
    if grep -qE -- "$2" "$out"; then
        fail "$1: expected no line matching '$2', got: $(grep -E -- "$2" "$out" | head -2 | tr '\n' '|')"
    else pass; fi
}

# --- 5: nearest and sweep keep the 1e6 Hz limit (the one change path checks every range) ---
mkdir -p "$tmp/xdg/springsim/presets"
plain 'set spring 1e14\nnearest\nsave bigf\nsweep\n' -n 1
has "nearest past 1e6 Hz" '^error mode 1 is at 2\.251e\+06 Hz, past the drive.s range \(0 < frequency <= 1e6 Hz\)'
has "sweep with every mode past 1e6 Hz" '^error a sweep needs a mode the drive reaches'
hasnt "sweep past 1e6 Hz" 'sweeping'
if grep -q '^frequency *= *1$' "$tmp/xdg/springsim/presets/bigf.ini" 2>/dev/null &&
    "$SPRINGSIM" -p bigf --modes >/dev/null 2>"$err"; then pass; else
    fail "the preset saved after a refused nearest: $(grep frequency "$tmp/xdg/springsim/presets/bigf.ini" 2>/dev/null) $(show "$err")"
fi
rm -f "$tmp/xdg/springsim/presets/bigf.ini"
# (at 0.01 m: the motor's default 0.1 m would make contacts at resonance, and the
# message would say that first)
plain 'sweep\n' -n 2 --spring 1e11 --amplitude 0.01
has "sweep capped at 1e6 Hz" '^ok sweeping 25164\.61\.\.130759\.13 Hz'

# --- 7: the sweep runs from half the first mode to 1.5 times the last (README) ---
# -n 2, k = 1000 N/m, m = 1 kg, motor end: w^2 = (2 -+ 1) 1000, f = 5.03 and 8.72 Hz.
plain 'sweep\n' -n 2 --spring 1000 --amplitude 0.01
has "sweep to 1.5 times the last mode" '^ok sweeping 2\.52\.\.13\.08 Hz'

# --- 9: the words ---
plain 'sweep\n' -n 1 --mass 1e-300 --spring 1e300
has "sweep with the modes not known" '^error a sweep needs the modes|^error a sweep needs a mode the drive reaches'
hasnt "sweep with the modes not known" 'needs the motor at the right end'
plain 'set damping 1e308\nset damping 1e200\n' -n 1
has "damping 1e308" '^ok Damping 1e\+308 N.s/m; warning: dt = 0\.01 s may be unstable with rk4: the stability limit of dt cannot be computed'
has "damping 1e200" '^ok Damping 1e\+200 N.s/m; warning: dt = 0\.01 s may be unstable'
hasnt "damping 1e308" 'dt < 0 s'
plain 'set dt 1e-320\n'
has "set dt 1e-320" "^error dt: '1e-320' is out of range for the interactive program"
refused "has COUNT '-5', which is out of range" --sweep 0.1:5:-5
refused "has COUNT '1.5', which is not a whole number" --sweep 0.1:5:1.5
refused "has a value that is not a number" --sweep 0.1:x:5

# --- 8: the velocity cap's note in --plain at most once a second of simulated time ---
plain 'set amplitude 9\nset frequency 3\nrun 20\n'
caps=$(grep -c '^event t=[0-9.]* the velocity cap' "$out")
last=$(grep '^event t=[0-9.]* the velocity cap' "$out" | tail -n 1)
if [ "$caps" -ge 2 ] && [ "$caps" -le 21 ] && ! grep '^event t=' "$out" |
    grep 'velocity cap' | awk '{ sub(/^t=/, "", $2); s = int($2); if (NR > 1 && s == prev) d = 1; prev = s } END { exit !d }'
then pass; else
    fail "--plain, amplitude 9 at 3 Hz for 20 s: $caps cap lines (expected 2 to 21, one a second)"
fi
# The count still adds up: the last line says every time the cap acted (about 20 a second).
n=$(echo "$last" | sed -n 's/.*acted \([0-9]*\) times.*/\1/p')
if [ -n "$n" ] && [ "$n" -ge 300 ]; then pass; else fail "--plain cap count: '$last'"; fi

# --- 10: -o takes every legal name, up to 255 bytes (the temporary name is kept short) ---
mkdir -p "$tmp/long"
for len in 244 245 250 255; do
    name=$(head -c "$len" /dev/zero | tr '\0' n)
    run --modes -o "$tmp/long/$name"
    if [ "$rc" -eq 0 ] && [ -s "$tmp/long/$name" ] && [ ! -s "$err" ]; then pass; else
        fail "--modes -o NAME of $len bytes: exit $rc, $(show "$err")"
    fi
done
name=$(head -c 256 /dev/zero | tr '\0' n)
run --modes -o "$tmp/long/$name"
[ "$rc" -eq 1 ] && grep -q 'File name too long' "$err" && pass ||
    fail "--modes -o NAME of 256 bytes: exit $rc, $(show "$err")"
left=$(ls -A "$tmp/long" | grep -v '^n*$' | tr '\n' ' ')
[ -z "$left" ] && pass || fail "-o with long names left: $left"

# --- 11: Unicode format characters (U+202E turns a line around, U+200B hides) escaped as
# control characters are, in a UTF-8 locale too; other UTF-8 (é) kept ---
rlo=$(printf '\342\200\256')
zwsp=$(printf '\342\200\213')
eacute=$(printf '\303\251')
printf 'preset a%sb%sc%s\n' "$rlo" "$zwsp" "$eacute" |
    LC_ALL=C.UTF-8 timeout 60 "$SPRINGSIM" --plain >"$out" 2>"$err"
if grep -qF "'a\u202eb\u200bc$eacute'" "$out" && ! grep -qF "$rlo" "$out" &&
    ! grep -qF "$zwsp" "$out"; then pass; else
    fail "--plain, preset a<U+202E>b<U+200B>c: $(grep error "$out" | od -c | head -3 | tr '\n' '|')"
fi
LC_ALL=C.UTF-8 "$SPRINGSIM" --modes --dt "0.01$rlo" >"$out" 2>"$err"
if grep -qF "'0.01\u202e'" "$err" && ! grep -qF "$rlo" "$err"; then pass; else
    fail "--dt 0.01<U+202E>: $(od -c "$err" | head -3 | tr '\n' '|')"
fi
mkdir -p "$tmp/fmt"
printf '[preset]\ndescription = evil %s title%s\n[system]\nmasses = 1\n' "$rlo" "$zwsp" \
    >"$tmp/fmt/evil.ini"
SPRINGSIM_PRESETS=$tmp/fmt LC_ALL=C.UTF-8 "$SPRINGSIM" --list-presets >"$out" 2>"$err"
if grep -qF 'evil \u202e title\u200b' "$out" && ! grep -qF "$rlo" "$out"; then pass; else
    fail "--list-presets, a description with U+202E: $(grep evil "$out" | od -c | head -3 | tr '\n' '|')"
fi
cp "$tmp/fmt/evil.ini" "$tmp/fmt/x${rlo}y.ini"
printf 'presets\n' | SPRINGSIM_PRESETS=$tmp/fmt LC_ALL=C.UTF-8 timeout 60 "$SPRINGSIM" --plain \
    >"$out" 2>"$err"
if grep -qF 'x\u202ey' "$out" && ! grep -qF "$rlo" "$out"; then pass; else
    fail "--plain presets, a name with U+202E: $(grep presets "$out" | od -c | head -4 | tr '\n' '|')"
fi

# --- 6: two programs racing: every export gets its own file, one save of a name wins ---
mkdir -p "$tmp/race"
cmds=$(i=0; while [ $i -lt 40 ]; do echo export; i=$((i + 1)); done)
(
    cd "$tmp/race" || exit 1
    echo "$cmds" | timeout 60 "$SPRINGSIM" --plain >a.out 2>&1 &
    echo "$cmds" | timeout 60 "$SPRINGSIM" --plain >b.out 2>&1
    wait
)
said=$(cat "$tmp/race/a.out" "$tmp/race/b.out" | grep -c '^ok exported')
files=$(ls "$tmp/race" | grep -c '^springsim-.*\.csv$')
if [ "$said" -eq 80 ] && [ "$files" -eq 80 ]; then pass; else
    fail "two --plain exporting 40 times each in one directory: $said 'ok exported', $files files"
fi
both=0
round=0
while [ $round -lt 20 ]; do
    rm -rf "$tmp/race/x"
    mkdir -p "$tmp/race/x"
    printf 'save race\n' | XDG_CONFIG_HOME=$tmp/race/x timeout 60 "$SPRINGSIM" --plain \
        >"$tmp/race/a.out" 2>&1 &
    printf 'save race\n' | XDG_CONFIG_HOME=$tmp/race/x timeout 60 "$SPRINGSIM" --plain \
        >"$tmp/race/b.out" 2>&1
    wait
    [ "$(cat "$tmp/race/a.out" "$tmp/race/b.out" | grep -c '^ok saved')" -eq 1 ] ||
        both=$((both + 1))
    round=$((round + 1))
done
[ "$both" -eq 0 ] && pass ||
    fail "two --plain saving 'race' at once: not exactly one 'ok saved' in $both of 20 rounds"

# --- 3: --integrator exact takes any N when its damping is Rayleigh's, dampers in
# proportion to the masses and the springs, with a force and a damper on the motor's spring
# too (stepped in the modes); otherwise it is refused where it would look hung, with the
# reason
dampers() { awk -v n="$1" 'BEGIN { for (i = 0; i < n; i++) printf "%s%g", i ? "," : "", 0.1 + 0.01 * i }'; }
refused "'exact' takes at most 20 masses with collisions (100 without) when the dampers are not proportional" \
    --headless --integrator exact -n 1000 --damping "$(dampers 1000)"
refused "'exact' takes at most 20 masses with collisions" --headless --integrator exact -n 21 \
    --damping "$(dampers 21)"
refused "'exact' takes at most 100 masses without collisions" --headless --integrator exact \
    -n 101 --no-collisions --mass "$(dampers 101)"
printf '[system]\nmasses = 300\nintegrator = exact\n' >"$tmp/exact.ini"
refused "exact.ini:3: integrator: 'exact' takes at most" --headless -p "$tmp/exact.ini" \
    --damping "$(dampers 300)"
accepted --headless --integrator exact -n 20 --duration 0.05 --damping "$(dampers 20)"
accepted --headless --integrator exact -n 100 --no-collisions --duration 0 --damping "$(dampers 100)"
accepted --modes --integrator exact -n 200 --damping "$(dampers 200)"
# proportional dampers: the default chain, an undamped one, c_i = 0.3 m_i
accepted --headless --integrator exact -n 1000 --duration 0.05
accepted --headless --integrator exact -n 300 --damping 0 --duration 0.05
accepted --headless --integrator exact -n 300 --mass "$(dampers 300)" \
    --damping "$(awk 'BEGIN { for (i = 0; i < 300; i++) printf "%s%.17g", i ? "," : "", 0.3 * (0.1 + 0.01 * i) }')" \
    --duration 0.05
# Rayleigh's with spring dampers (the motor's too) and a force; spring dampers off it
accepted --headless --integrator exact -n 300 --spring-damping 0.01 --damping 0.1 --force 1 \
    --force-on 150 --duration 0.05
refused "'exact' takes at most 20 masses with collisions (100 without) when the dampers are not proportional" \
    --headless --integrator exact -n 300 --spring-damping "$(dampers 301)"
accepted --headless -p "$tmp/exact.ini" --duration 0.05

# --- 12: an option the mode would ignore is refused in one line, as --plain -o is ---
refused "--energy: applies to --headless's rows" --summary --energy
refused "--sample: applies to --headless's rows" --summary --sample 1
refused "--energy: applies to --headless's rows" --headless --summary --energy
refused "--energy: applies to --headless, not to --plain" --plain --energy
refused "--duration: applies to --headless, not to --plain" --plain --duration 3
refused "--sample: applies to --headless, not to --plain" --plain --sample 1
refused "(it was given twice)" --modes --modes
refused "(it was given twice)" --sweep 1:2:3 --sweep 1:2:4
refused "--output: applies to the output of --headless" --plain -o "$tmp/x.csv"
# A preset may set them for every mode: then they are left alone, and --meta's command
# line (which repeats the run) leaves out what --summary would refuse.
printf '[run]\nenergy = true\nsample = 0.5\n' >"$tmp/series.ini"
run --summary --meta -p "$tmp/series.ini" --duration 0.1
if [ "$rc" -eq 0 ] && ! grep -q -- '--energy\|--sample' "$out"; then pass; else
    fail "$cmd: exit $rc, $(show "$out")"
fi
set -- $(sed -n 's/^# springsim //p' "$out" | sed -n 2p)
run "$@"
if [ "$rc" -eq 0 ] && [ "$(grep -vc '^#' "$out")" -eq 2 ]; then pass; else
    fail "the --summary --meta line run again: exit $rc, $(show "$err")"
fi
run --headless --energy --sample 0.05 --duration 0.1
[ "$rc" -eq 0 ] && pass || fail "$cmd: exit $rc"

summary
