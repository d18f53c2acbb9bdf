#!/bin/sh
# tests/cli.sh: end-to-end tests of the real binary's command line (springsim(1)): bad
# options and values, negative values, the headless CSV, --modes and --sweep against
# closed forms. Output files, presets and --help are in tests/cli-files.sh.
# Run from the repository root as `sh tests/cli.sh`, with SPRINGSIM naming the binary
# (default ./springsim). Prints one line per failing case, then exactly one summary line
# "cli: N passed, M failed"; exits non-zero if anything failed.

NAME=cli
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/cli.sh"
trap 'exit 1' HUP INT TERM

# Keep the user's own presets out of the way: an empty user preset directory, no
# $SPRINGSIM_PRESETS. Cases that need them set them for one run.
plain_env

# ---------------------------------------------------------------------------------------
# 1. Bad options and values: exit 2, one line naming option and value, nothing on stdout.

run --headless --dt abc
expect_equal "springsim --headless --dt abc: the message" \
    "springsim: --dt: 'abc' is not a number (expected 0 < dt <= 0.05)" "$(cat "$err")"

expect_usage_error --bogus -- --headless --bogus
# Options only the command line gives, meant for another mode: said, not ignored.
expect_usage_error --meta --plain -- --plain --meta
expect_usage_error --output "the interactive program" -- -o x.csv
expect_usage_error --meta --list-presets -- --list-presets --meta
expect_usage_error --plain-every --headless -- --headless --plain-every 2
expect_usage_error --plain-every "the interactive program" -- --plain-every 2
expect_usage_error --dt "'abc'" -- --headless --dt abc
expect_usage_error --dt "'0.01x'" -- --headless --dt 0.01x
expect_usage_error --dt "'nan'" -- --headless --dt nan
expect_usage_error --amplitude "'inf'" -- --headless --amplitude inf
expect_usage_error --dt "'0'" -- --headless --dt 0
expect_usage_error --dt "'0.06'" -- --headless --dt 0.06
expect_usage_error --dt "'0.06'" -- --headless --dt=0.06
expect_usage_error --masses "'0'" -- --headless --masses 0
expect_usage_error --masses "'1001'" -- --headless --masses 1001
expect_usage_error --masses "'2.5'" -- --headless --masses 2.5
expect_usage_error --masses "'-1'" -- --headless -n -1
expect_usage_error --mass "'0'" -- --headless --mass 0
expect_usage_error --mass "'-1'" -- --headless --mass -1
expect_usage_error --mass "'1,-1'" -- --headless --mass 1,-1
expect_usage_error --spring "'-1'" -- --headless --spring -1
expect_usage_error --spring-damping "'-0.5'" -- --headless --spring-damping -0.5
expect_usage_error --spring-damping "'nan'" -- --headless --spring-damping nan
expect_usage_error --spring-damping "'inf'" -- --headless --spring-damping inf
expect_usage_error --spring-damping "2 values for 3 springs" -- --headless --spring-damping 1,2
expect_usage_error --spring-damping "square" -- --headless --spring-damping 0.5 --wave square
# the motor's spring is the list's last, N+1, named as elsewhere
expect_usage_error --spring-damping "expected 0 for spring 3 (2–motor)" -- --headless \
    --spring-damping 0,0,1 --wave square
expect_usage_error --spring-damping "expected 0 for spring 201 (200–motor)" -- --headless \
    -n 200 --spring-damping 1 --wave sawtooth
expect_usage_error --force "'-1'" -- --headless --force -1
expect_usage_error --force "'nan'" -- --headless --force nan
expect_usage_error --force-on "'0'" -- --headless --force-on 0 --force 1
expect_usage_error --force-on "'3'" "1 <= K <= 2" -- --headless --force-on 3 --force 1
expect_usage_error --force-on "'1.5'" -- --headless --force-on 1.5
expect_usage_error --damping "'-0.1'" -- --headless --damping -0.1
expect_usage_error --amplitude "'-1'" -- --headless --amplitude -1
expect_usage_error --frequency "'0'" -- --headless --frequency 0
expect_usage_error --duration "'-1'" -- --headless --duration -1
expect_usage_error --sample "'0'" -- --headless --sample 0
expect_usage_error --fps "'0'" "1 <= fps <= 60" -- --fps 0
expect_usage_error --fps "'61'" -- --fps 61
expect_usage_error --fps "'2.5'" "whole number" -- --fps 2.5
expect_usage_error --seed "'x'" -- --headless --random --seed x
expect_usage_error --boundary "'x'" -- --headless --boundary x
expect_usage_error --wave "'x'" -- --headless --wave x
# Wrong list lengths are found only once N is known, but are still bad values.
expect_usage_error --mass "'1,2'" -- --headless --masses 3 --mass 1,2
expect_usage_error --spring "'1,2'" -- --headless -n 2 --spring 1,2
expect_usage_error --x0 "'1,2,3'" -- --headless -n 2 --x0 1,2,3
expect_usage_error --v0 "'1,2,3'" -- --headless -n 2 --v0 1,2,3
expect_usage_error --mass "'1,,2'" -- --headless --mass 1,,2
expect_usage_error --dt -- --headless --dt
expect_usage_error --preset "'nosuchpreset'" -- --headless -p nosuchpreset
expect_usage_error --sweep "'1:0.5:10'" -- --sweep 1:0.5:10
expect_usage_error --sweep "'0:1:10'" -- --sweep 0:1:10
expect_usage_error --sweep "'0.1:1:1'" -- --sweep 0.1:1:1
expect_usage_error --sweep "'a:b:c'" -- --sweep a:b:c
# a motor standing still drives nothing, as a wall does not: refused without a force
expect_usage_error --sweep "amplitude is 0, which does not drive" -- --amplitude 0 --sweep 0.5:1:2
expect_usage_error --sweep "does not drive" -- --amplitude 0 --spring-cubic 1 --sweep 0.5:1:2
expect_usage_error --sweep "'0.1:1'" -- --sweep 0.1:1
expect_usage_error --sweep "'0.1:1:10:3'" -- --sweep 0.1:1:10:3
expect_usage_error --sweep "'wall'" -- --sweep 0.1:1:10 --boundary wall
expect_usage_error "'stray'" -- --headless stray
expect_usage_error --headless --modes -- --headless --modes
expect_usage_error --modes --sweep -- --modes --sweep 0.1:1:10

# ---------------------------------------------------------------------------------------
# 2. Negative values in both spellings, with the same result.

if expect_ok --headless --duration 0.1 --x0 -0.5; then
    cp "$out" "$tmp/neg1"
    expect_equal "$cmd: x1 of the first row" "-0.5" "$(column "$out" x1 1)"
fi
if expect_ok --headless --duration 0.1 --x0=-0.5; then
    expect_same_output "--x0 -0.5 against --x0=-0.5" "$tmp/neg1" "$out"
fi

# ---------------------------------------------------------------------------------------
# 3. Headless CSV: headers, row counts, t grid, fields, precision.

if expect_ok --headless --duration 1; then
    expect_equal "$cmd: header" "t,x1,x2,v1,v2,a1,a2,motor" "$(first_line "$out")"
    expect_equal "$cmd: data rows" 101 "$(data_rows "$out")"
    check_csv "$out" "$cmd"
    expect_equal "$cmd: first t" 0 "$(column "$out" t 1)"
    expect_equal "$cmd: last t" 1 "$(column "$out" t 101)"
    # At least 10 significant digits: a velocity mid-run is not a round number.
    v=$(column "$out" v2 50)
    digits=$(printf '%s\n' "$v" | sed 's/[eE].*//; s/[-.]//g; s/^0*//')
    if [ "${#digits}" -ge 10 ]; then pass; else
        fail "$cmd: v2 at row 50 is '$v', fewer than 10 significant digits"
    fi
    cp "$out" "$tmp/default.csv"
fi
if expect_ok --headless -n 3 --duration 0.1; then
    expect_equal "$cmd: header" "t,x1,x2,x3,v1,v2,v3,a1,a2,a3,motor" "$(first_line "$out")"
    check_csv "$out" "$cmd"
fi
if expect_ok --headless --energy --duration 0.5; then
    expect_equal "$cmd: header" \
        "t,x1,x2,v1,v2,a1,a2,motor,kinetic,potential,dissipated,motor_work,contact,force_work" \
        "$(first_line "$out")"
    # 2 x 3 + 2 columns of motion, 6 of energy, on every row (check_csv: each one finite)
    expect_equal "$cmd: columns" 14 "$(awk -F, 'NR == 1 { print NF }' "$out")"
    check_csv "$out" "$cmd"
fi
if expect_ok --headless --duration 1 --sample 0.1; then
    expect_equal "$cmd: data rows" 11 "$(data_rows "$out")"
    # the rows are the default run's every tenth row
    awk 'NR == 1 || (NR - 2) % 10 == 0' "$tmp/default.csv" >"$tmp/every10"
    expect_same_output "$cmd against every 10th row of --duration 1" "$tmp/every10" "$out"
fi
if expect_ok --headless --duration 0; then
    expect_equal "$cmd: data rows" 1 "$(data_rows "$out")"
    expect_equal "$cmd: t" 0 "$(column "$out" t 1)"
fi
# --sample is rounded to whole steps: 0.05 / 0.02 = 2.5 -> 3 steps (round half away from
# zero), so 50 steps give rows at steps 0, 3, ..., 48: 17 rows, the last at t = 0.96.
if expect_ok --headless --duration 1 --dt 0.02 --sample 0.05; then
    expect_equal "$cmd: data rows" 17 "$(data_rows "$out")"
    expect_equal "$cmd: t of row 2" 0.06 "$(column "$out" t 2)"
    expect_equal "$cmd: last t" 0.96 "$(column "$out" t 17)"
fi
# A sample shorter than dt still gives every step.
expect_rows 11 --headless --duration 0.1 --sample 0.001
# Other waveforms and ends make finite CSV too; motor is 0 for wall.
for w in square triangle sawtooth; do
    expect_ok --headless --duration 2 --wave "$w" && check_csv "$out" "$cmd"
done
if expect_ok --headless --duration 1 --boundary wall --x0 0.3; then
    check_csv "$out" "$cmd"
    m=$(awk -F, 'NR > 1 && $NF != 0 { print $NF; exit }' "$out")
    expect_equal "$cmd: motor column all 0" "" "$m"
fi

# ---------------------------------------------------------------------------------------
# 4. --modes against the closed form of the uniform chain.

# check_modes N: -n N --modes, frequencies 2 sqrt(k/m) sin(j pi / (2 (N+1))) / 2 pi with
# k = 10, m = 1 to 1e-9 relative, ascending, each shape's largest |component| is +1. The
# dampers (0.1 on masses of 1 kg) are proportional to M, so the modes do not mix and each
# is lambda^2 + 0.1 lambda + w^2 = 0: damping ratio 0.1 / (2 w), damped frequency
# w sqrt(1 - ratio^2) / 2 pi, eigen frequency |lambda| / 2 pi = w / 2 pi.
check_modes() {
    nm=$1
    shift
    expect_ok --modes -n "$nm" "$@" || return
    hdr=mode,frequency_hz
    i=1
    while [ "$i" -le "$nm" ]; do hdr="$hdr,x$i"; i=$((i + 1)); done
    expect_equal "$cmd: header" "$hdr,damping_ratio,damped_frequency_hz,eigen_frequency_hz" \
        "$(first_line "$out")"
    expect_equal "$cmd: rows" "$nm" "$(data_rows "$out")"
    bad=$(awk -F, -v n="$nm" '
        function abs(x) { return x < 0 ? -x : x }
        NR == 1 { next }
        {
            j = NR - 1
            pi = atan2(0, -1)
            w = 2 * sqrt(10) * sin(j * pi / (2 * (n + 1)))
            want = w / (2 * pi)
            if ($1 != j) { print "row " j " is mode " $1; exit }
            if (abs($2 - want) > 1e-9 * want) { print "mode " j " f = " $2 ", expected " want; exit }
            if (j > 1 && $2 <= last) { print "mode " j " not above mode " j - 1; exit }
            last = $2
            if (NF != n + 5) { print "mode " j " has " NF - 5 " components"; exit }
            max = -2; min = 2
            for (i = 3; i <= n + 2; i++) { if ($i + 0 > max) max = $i + 0; if ($i + 0 < min) min = $i + 0 }
            if (max != 1 || min < -1) { print "mode " j " shape " $0 " is not scaled to +1"; exit }
            z = 0.1 / (2 * w)
            if (abs($(n + 3) - z) > 1e-9 * z) { print "mode " j " ratio " $(n + 3) ", expected " z; exit }
            fd = w * sqrt(1 - z * z) / (2 * pi)
            if (abs($(n + 4) - fd) > 1e-9 * fd) { print "mode " j " damped " $(n + 4) ", expected " fd; exit }
            if (abs($(n + 5) - want) > 1e-9 * want) { print "mode " j " eigen " $(n + 5) ", expected " want; exit }
        }' "$out")
    if [ -z "$bad" ]; then pass; else fail "$cmd: $bad"; fi
}
check_modes 2
check_modes 5
# the wall end has the same modes
check_modes 3 --boundary wall
# Overdamped: one mass, k = 20 (both springs), m = 1, c = 20 > 2 sqrt(k m): both
# eigenvalues real, ratio c / (2 sqrt(k m)) = sqrt(5), damped frequency 0; |lambda| / 2 pi
# the geometric mean of the two, sqrt(k / m) / 2 pi (their product is k / m).
if expect_ok --modes -n 1 --damping 20; then
    expect_equal "$cmd: header" \
        "mode,frequency_hz,x1,damping_ratio,damped_frequency_hz,eigen_frequency_hz" \
        "$(first_line "$out")"
    bad=$(awk -F, 'NR == 2 { d = $4 - sqrt(5); if (d < 0) d = -d
        w = sqrt(20) / (2 * atan2(0, -1)); e = $6 - w; if (e < 0) e = -e
        if (d > 1e-9 || $5 != 0) print "ratio " $4 " (expected sqrt 5), damped " $5 " (expected 0)"
        else if (e > 1e-9 * w) print "eigen frequency " $6 " (expected " w ")" }' "$out")
    if [ -z "$bad" ]; then pass; else fail "$cmd: $bad"; fi
fi

# ---------------------------------------------------------------------------------------
# 5. --sweep against the 1-DOF steady state: amp = k A / sqrt((2k - m w^2)^2 + (c w)^2),
# phase atan2(-c w, 2k - m w^2) in degrees.

if expect_ok --sweep 0.1:2:20 -n 1; then
    expect_equal "$cmd: header" "frequency_hz,amp1,phase1" "$(first_line "$out")"
    expect_equal "$cmd: rows" 20 "$(data_rows "$out")"
    expect_equal "$cmd: first frequency" 0.1 "$(column "$out" frequency_hz 1)"
    expect_equal "$cmd: last frequency" 2 "$(column "$out" frequency_hz 20)"
    bad=$(awk -F, '
        function abs(x) { return x < 0 ? -x : x }
        NR == 1 { next }
        {
            r = NR - 2
            f = 0.1 + 1.9 * r / 19
            if (abs($1 - f) > 1e-12) { print "row " r + 1 " frequency " $1 ", expected " f; exit }
            w = 2 * atan2(0, -1) * $1
            k = 10; m = 1; c = 0.1; A = 0.1 # the default amplitude
            want = k * A / sqrt((2 * k - m * w * w) ^ 2 + (c * w) ^ 2)
            if (abs($2 - want) > 1e-9 * want) { print "f = " $1 ": amp " $2 ", expected " want; exit }
            ph = atan2(-c * w, 2 * k - m * w * w) * 180 / atan2(0, -1)
            if (abs($3 - ph) > 1e-9 * 180) { print "f = " $1 ": phase " $3 ", expected " ph; exit }
        }' "$out")
    if [ -z "$bad" ]; then pass; else fail "$cmd: $bad"; fi
fi
# amplitudes scale with A
if expect_ok --sweep 0.1:2:20 -n 1 --amplitude 0.5; then
    bad=$(awk -F, 'NR > 1 { w = 2 * atan2(0, -1) * $1
        want = 5 / sqrt((20 - w * w) ^ 2 + (0.1 * w) ^ 2)
        d = $2 - want; if (d < 0) d = -d
        if (d > 1e-9 * want) { print "f = " $1 ": amp " $2 ", expected " want; exit } }' "$out")
    if [ -z "$bad" ]; then pass; else fail "$cmd: $bad"; fi
fi

# Lightly damped, far below resonance (0.712 Hz) the mass follows the motor, far above it
# moves against it: a lag near 0 and near -180 degrees; the columns come N of each.
if expect_ok --sweep 0.05:5:2 -n 1 --damping 0.01; then
    bad=$(awk -F, 'NR == 2 && !($3 <= 0 && $3 > -0.1) { print "below: phase " $3 }
        NR == 3 && !($3 < -179.9 && $3 > -180) { print "above: phase " $3 }' "$out")
    if [ -z "$bad" ]; then pass; else fail "$cmd: $bad"; fi
fi
if expect_ok --sweep 0.1:1:3 -n 3; then
    expect_equal "$cmd: header" "frequency_hz,amp1,amp2,amp3,phase1,phase2,phase3" \
        "$(first_line "$out")"
    expect_equal "$cmd: columns in every row" 7 \
        "$(awk -F, '{ print NF }' "$out" | sort -u | tr '\n' ' ' | sed 's/ $//')"
fi

echo "cli: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
