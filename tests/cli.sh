#!/bin/sh
# tests/cli.sh: end-to-end tests of the real binary's command line (springsim(1), OPTIONS and PRESETS).
# Run from the repository root as `sh tests/cli.sh`, with SPRINGSIM naming the binary
# (default ./springsim). Prints one line per failing case, then exactly one summary line
# "cli: N passed, M failed"; exits non-zero if anything failed.

NAME=cli
. "$(dirname "$0")/lib/check.sh"
trap 'exit 1' HUP INT TERM

# Keep the user's own presets out of the way: an empty user preset directory, no
# $SPRINGSIM_PRESETS. Cases that need them set them for one run.
plain_env

lines() { awk 'END { print NR }' "$1"; } # counts a last line without a newline too
first_line() { sed -n 1p "$1" 2>/dev/null; }
data_rows() { awk 'NR > 1' "$1" 2>/dev/null | awk 'END { print NR }'; }

# shows a file's first lines in one line, for failure messages
show() { head -c 300 "$1" | tr '\n' '|'; }

# expect_ok ARGS...: runs and checks it exited 0 with nothing on stderr. Returns 1 (after
# reporting) otherwise, so a caller can skip the checks that would only repeat it.
expect_ok() {
    run "$@"
    if [ "$rc" -ne 0 ] || [ -s "$err" ]; then
        fail "$cmd: expected exit 0 and empty stderr, got exit $rc, stderr: $(show "$err")"
        return 1
    fi
    return 0
}

# expect_usage_error NEEDLE... -- ARGS...: a bad option or value. Exit 2,
# exactly one line on stderr starting "springsim: " and naming the option and value
# (each NEEDLE must appear in it), nothing on stdout.
expect_usage_error() {
    needles=
    while [ "$1" != -- ]; do
        needles="$needles$1
"
        shift
    done
    shift
    expect_one_line_error 2 "$needles" "$@"
}

# expect_one_line_error STATUS NEEDLES ARGS...: NEEDLES is newline-separated.
expect_one_line_error() {
    want=$1
    needles=$2
    shift 2
    run "$@"
    bad=
    [ "$rc" -eq "$want" ] || bad="$bad exit $rc (expected $want);"
    [ -s "$out" ] && bad="$bad stdout not empty: $(show "$out");"
    n=$(lines "$err")
    [ "$n" -eq 1 ] || bad="$bad $n lines on stderr (expected 1);"
    line=$(first_line "$err")
    case $line in springsim:\ *) ;; *) bad="$bad stderr does not start 'springsim: ';" ;; esac
    old_ifs=$IFS
    IFS='
'
    set -f # a needle like [bogus] is not a glob
    for needle in $needles; do
        case $line in *"$needle"*) ;; *) bad="$bad stderr does not name \"$needle\";" ;; esac
    done
    IFS=$old_ifs
    set +f
    if [ -n "$bad" ]; then
        fail "$cmd:$bad stderr: $(show "$err")"
    else
        pass
    fi
}

# expect_equal WHAT EXPECTED ACTUAL
expect_equal() {
    if [ "$2" = "$3" ]; then pass; else fail "$1: expected '$2', got '$3'"; fi
}

# expect_rows N ARGS...: the command succeeds and prints N data rows after its header.
expect_rows() {
    want=$1
    shift
    expect_ok "$@" || return
    expect_equal "$cmd: data rows" "$want" "$(data_rows "$out")"
}

# expect_same_output WHAT FILE1 FILE2
expect_same_output() {
    if cmp -s "$2" "$3"; then pass; else fail "$1: outputs differ"; fi
}

# check_csv FILE WHAT: every row has as many fields as the header, and every field of
# every data row is a plain finite number (no nan, no inf, nothing empty).
check_csv() {
    bad=$(awk -F, '
        NR == 1 { nf = NF; next }
        NF != nf { print "row " NR - 1 " has " NF " fields, header has " nf; exit }
        { for (i = 1; i <= NF; i++)
              if ($i !~ /^-?[0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?$/) {
                  print "row " NR - 1 " field " i " is \"" $i "\""; exit } }' "$1")
    if [ -z "$bad" ]; then pass; else fail "$2: $bad"; fi
}

# expect_no_tmp DIR WHAT: no temporary output files (FILE.tmp-XXXXXX) left behind.
expect_no_tmp() {
    left=
    for g in "$1"/*.tmp* "$1"/.*.tmp*; do
        [ -e "$g" ] && left="$left $(basename "$g")"
    done
    if [ -z "$left" ]; then pass; else fail "$2: temporary files left in $1: $left"; fi
}

# column FILE NAME ROW: the field of data row ROW (1 = first) under header NAME.
column() {
    awk -F, -v name="$2" -v row="$3" '
        NR == 1 { for (i = 1; i <= NF; i++) if ($i == name) c = i; next }
        NR - 1 == row { print $c; exit }' "$1" 2>/dev/null
}

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

# ---------------------------------------------------------------------------------------
# 6. -o: written whole or not at all.

mkdir "$tmp/o"
f=$tmp/o/run.csv
echo old >"$f"
if expect_ok --headless --duration 0.5 -o "$f"; then
    expect_equal "$cmd: stdout" "" "$(cat "$out")"
    "$SPRINGSIM" --headless --duration 0.5 >"$tmp/o.stdout" 2>/dev/null
    expect_same_output "$cmd: FILE against standard output" "$tmp/o.stdout" "$f"
fi
cp "$f" "$tmp/o.before"
# rejected before running: the file stays as it was
expect_usage_error --dt "'abc'" -- --headless --duration 0.5 -o "$f" --dt abc
expect_same_output "$cmd: FILE after a rejected run" "$tmp/o.before" "$f"
expect_no_tmp "$tmp/o" "$cmd"
# fails after it started writing (the numbers blow up): still untouched, exit 1
run --headless --no-collisions --spring 1e6 --dt 0.05 --duration 5 -o "$f"
expect_equal "$cmd: exit status of a blown-up run" 1 "$rc"
expect_same_output "$cmd: FILE after a blown-up run" "$tmp/o.before" "$f"
expect_no_tmp "$tmp/o" "$cmd"
case $(cat "$err") in
*"dt"*) pass ;;
*) fail "$cmd: expected a message naming dt, got: $(show "$err")" ;;
esac
# --modes and --sweep write FILE too
if expect_ok --modes -o "$tmp/o/modes.csv"; then
    expect_equal "$cmd: header in FILE" \
        "mode,frequency_hz,x1,x2,damping_ratio,damped_frequency_hz,eigen_frequency_hz" \
        "$(first_line "$tmp/o/modes.csv")"
    expect_equal "$cmd: stdout" "" "$(cat "$out")"
fi
if expect_ok --sweep 0.5:1:3 -o "$tmp/o/sweep.csv"; then
    expect_equal "$cmd: rows in FILE" 3 "$(data_rows "$tmp/o/sweep.csv")"
fi
expect_no_tmp "$tmp/o" "after -o runs"
# write errors: path and reason, exit 1
if [ -w /dev/full ]; then
    expect_one_line_error 1 "/dev/full
No space left on device" --headless --duration 1 -o /dev/full
fi
expect_one_line_error 1 "/nonexistent-dir/x.csv
No such file or directory" --headless --duration 0.1 -o /nonexistent-dir/x.csv
expect_one_line_error 1 "$tmp/o
Is a directory" --headless --duration 0.1 -o "$tmp/o"

# ---------------------------------------------------------------------------------------
# 7. Presets: the built-in list, search path, shadowing, options over presets.

# the built-ins are whatever presets/*.ini holds beside the binary
builtin_dir=$(dirname "$SPRINGSIM")/presets
builtins=
for p in "$builtin_dir"/*.ini; do
    [ -f "$p" ] && builtins="$builtins $(basename "$p" .ini)"
done
[ -n "$builtins" ] || echo "note: no built-in presets in $builtin_dir yet"

run --list-presets
expect_equal "$cmd: exit status" 0 "$rc"
for name in $builtins; do
    expect_equal "$cmd: lines starting '$name'" 1 "$(grep -c "^${name}[[:space:]]" "$out")"
done
for name in $builtins; do
    if expect_ok -p "$name" --headless --duration 1; then
        check_csv "$out" "$cmd"
    fi
done

mkdir -p "$tmp/p" "$tmp/env" "$tmp/xdg2/springsim/presets"
printf '[system]\nmasses = 3\n' >"$tmp/p/three.ini"
expect_rows 3 -p "$tmp/p/three.ini" --modes
# options override a preset wherever it stands on the line
expect_rows 4 --masses 4 -p "$tmp/p/three.ini" --modes
expect_rows 4 -p "$tmp/p/three.ini" --masses 4 --modes
case " $builtins " in *" resonance "*) expect_rows 4 --masses 4 -p resonance --modes ;; esac
# a relative path works too
(cd "$tmp" && "$SPRINGSIM" -p p/three.ini --modes >"$out" 2>"$err")
expect_equal "springsim -p p/three.ini --modes (relative path): rows" 3 "$(data_rows "$out")"

# $SPRINGSIM_PRESETS is searched, and listed
printf '[preset]\ndescription = four from the env\n[system]\nmasses = 4\n' >"$tmp/env/mine.ini"
printf '[system]\nmasses = 4\n' >"$tmp/env/resonance.ini"
SPRINGSIM_PRESETS=$tmp/env
export SPRINGSIM_PRESETS
expect_rows 4 -p mine --modes
run --list-presets
expect_equal "$cmd with SPRINGSIM_PRESETS: the line for mine" "mine four from the env" \
    "$(grep '^mine' "$out" | tr -s ' ')"
# the user's directory shadows $SPRINGSIM_PRESETS and the built-ins
printf '[system]\nmasses = 3\n' >"$tmp/xdg2/springsim/presets/resonance.ini"
XDG_CONFIG_HOME=$tmp/xdg2
expect_rows 3 -p resonance --modes
unset SPRINGSIM_PRESETS
expect_rows 3 -p resonance --modes
XDG_CONFIG_HOME=$tmp/xdg

# ---------------------------------------------------------------------------------------
# 8. Preset files: errors as FILE:LINE, exit 2; file errors exit 1; comments, continuations.

# expect_preset_error NAME LINE NEEDLE CONTENT: CONTENT (with \n escapes) written to
# NAME.ini must be refused with "springsim: PATH:LINE: ..." containing NEEDLE.
expect_preset_error() {
    pf=$tmp/p/$1.ini
    printf '%b' "$4" >"$pf"
    expect_one_line_error 2 "springsim: $pf:$2: 
$3" -p "$pf" --headless --duration 0.1
}
expect_preset_error section 3 "[bogus]" '; a comment\n\n[bogus]\nmasses = 2\n'
expect_preset_error key 3 bogus '[system]\nmasses = 2\nbogus = 1\n'
expect_preset_error wrongsection 2 wave '[system]\nwave = sine\n'
expect_preset_error value 2 "dt: 'abc' is not a number" '[system]\ndt = abc\n'
expect_preset_error range 3 "masses: '0'" '[system]\n\nmasses = 0\n'
expect_preset_error syntax 3 "" '[system]\nmasses = 2\nthis line has no equals sign\n'
expect_preset_error twice 4 masses '[system]\nmasses = 2\nmass = 1\nmasses = 3\n'
expect_preset_error nosection 1 masses 'masses = 2\n'
expect_preset_error listlen 3 mass '[system]\nmasses = 2\nmass = 1,2,3\n'
long=$(awk 'BEGIN { for (i = 0; i < 185; i++) s = s "x"; print s }')
expect_preset_error longline 2 "" "[preset]\ndescription = $long\n" # 199 characters
# a line of 198 characters is still fine
printf '[preset]\ndescription = %s\n[system]\nmasses = 3\n' "${long%x}" >"$tmp/p/long198.ini"
expect_rows 3 -p "$tmp/p/long198.ini" --modes

expect_one_line_error 1 "$tmp/p/missing.ini
No such file or directory" -p "$tmp/p/missing.ini" --headless
mkdir "$tmp/p/adir"
expect_one_line_error 1 "$tmp/p/adir
Is a directory" -p "$tmp/p/adir" --headless

cat >"$tmp/p/comments.ini" <<'EOF'
; a comment
# another comment
[system]
  ; an indented comment
masses = 3 # trailing comment
mass = 2 ; trailing comment
[motor]
frequency = 0.5
EOF
if expect_ok -p "$tmp/p/comments.ini" --modes; then
    cp "$out" "$tmp/comments.modes"
    expect_ok -n 3 --mass 2 --modes && expect_same_output "$cmd against the commented preset" \
        "$out" "$tmp/comments.modes"
fi

# A long list goes on over indented lines, with or without a comma ending the line
# before (the program's own preset writer ends it with one).
expect_ok -n 12 --mass 1,1,1,1,1,1,2,2,2,2,2,2 --modes && cp "$out" "$tmp/12.modes"
expect_ok -n 12 --modes && cp "$out" "$tmp/ones.modes"
if cmp -s "$tmp/12.modes" "$tmp/ones.modes"; then
    fail "springsim -n 12 --modes: the same with masses 1 and 2 as with all ones"
else
    pass
fi
for comma in ',' ''; do
    pf=$tmp/p/continued$comma.ini
    printf '[system]\nmasses = 12\nmass = 1, 1, 1, 1, 1, 1%s\n    2, 2, 2, 2, 2, 2\n' \
        "$comma" >"$pf"
    expect_ok -p "$pf" --headless --duration 0.1 && check_csv "$out" "$cmd"
    expect_ok -p "$pf" --modes &&
        expect_same_output "$cmd against -n 12 --mass 1,1,1,1,1,1,2,2,2,2,2,2" \
            "$tmp/12.modes" "$out"
done

# ---------------------------------------------------------------------------------------
# 9. --help and --version.

if expect_ok --help; then
    for o in preset masses mass spring damping dt boundary wave amplitude frequency x0 v0 \
        random seed no-collisions duration sample output energy integrator headless modes \
        sweep list-presets keys fps low-bandwidth help version; do
        if grep -Eq -e "--$o([^a-z0-9-]|\$)" "$out"; then pass; else fail "$cmd: does not mention --$o"; fi
    done
    for o in -p -n -o; do
        if grep -q -- "$o," "$out"; then pass; else fail "$cmd: does not mention $o"; fi
    done
fi
if expect_ok --version; then
    if grep -q '^springsim [0-9][^ ]*$' "$out" && [ "$(lines "$out")" -eq 1 ]; then pass; else
        fail "$cmd: expected one line 'springsim VERSION', got: $(show "$out")"
    fi
fi

# 12. Found in review: every --preset given must exist; a huge --sample means only the
# first row; a sweep is bounded like the drive; a negative seed is out of range; a
# key repeated in a repeated section is an error; -o through a symbolic link writes the
# file it points to.
expect_usage_error --preset "'nosuch'" -- -p nosuch -p resonance --modes
expect_usage_error --masses "'20'" "interactive" -- -n 20
expect_usage_error --dt "'0.0005'" "interactive" -- --dt 0.0005
if expect_ok --headless --duration 0.05 --sample 1e300; then
    expect_equal "--sample 1e300: data rows" 1 "$(data_rows "$out")"
fi
expect_usage_error --sweep "'1:1e308:4'" "<= 1e6" -- --sweep 1:1e308:4
expect_usage_error --frequency "'1e12'" "<= 1e6" -- --headless --frequency 1e12
expect_usage_error --seed "'-1'" "out of range" -- --headless --seed -1
printf '[system]\nmass = 1\n[system]\nmass = 2\n' >"$tmp/twice.ini"
expect_one_line_error 2 "twice.ini:4:
'mass' is given twice" -p "$tmp/twice.ini" --modes
printf 'old\n' >"$tmp/target.csv"
ln -s target.csv "$tmp/link.csv"
if expect_ok --headless --duration 0.1 -o "$tmp/link.csv"; then
    if [ -L "$tmp/link.csv" ] && [ "$(data_rows "$tmp/target.csv")" -eq 11 ]; then pass; else
        fail "-o through a symlink: the link was replaced or the target not written"
    fi
fi

# 13. Integrators and the limits of dt : --integrator, its preset
# key, and the warnings said once on standard error before a run, exit status unchanged.
run --headless --integrator x
expect_equal "$cmd: the message" \
    "springsim: --integrator: 'x' is not an integrator (expected euler, semi-implicit, verlet, rk4 or exact)" \
    "$(cat "$err")"
expect_equal "$cmd: exit status" 2 "$rc"
expect_usage_error --integrator "'RK4'" -- --headless --integrator RK4
expect_usage_error --integrator -- --headless --integrator
for i in euler semi-implicit verlet rk4; do
    if expect_ok --headless --integrator "$i" --duration 1 --dt 0.0004; then
        check_csv "$out" "$cmd"
        cp "$out" "$tmp/int-$i.csv"
    fi
done
expect_rows 1 --headless --integrator exact --duration 0
# the integrators differ, and rk4 is the default
if cmp -s "$tmp/int-euler.csv" "$tmp/int-rk4.csv"; then fail "--integrator euler and rk4 gave the same"; else pass; fi
expect_ok --headless --duration 1 --dt 0.0004 &&
    expect_same_output "--integrator rk4 against the default" "$tmp/int-rk4.csv" "$out"
# a preset key in [system], the same as the option
printf '[system]\nintegrator = verlet\n' >"$tmp/p/verlet.ini"
expect_ok -p "$tmp/p/verlet.ini" --headless --duration 1 --dt 0.0004 &&
    expect_same_output "integrator = verlet in a preset" "$tmp/int-verlet.csv" "$out"
expect_preset_error integrator-section 2 integrator '[motor]\nintegrator = rk4\n'
expect_preset_error integrator-value 2 "integrator: 'leapfrog' is not an integrator" \
    '[system]\nintegrator = leapfrog\n'

# expect_warnings STATUS NEEDLES ARGS...: exits STATUS; every line of stderr starts
# "springsim: "; each newline-separated NEEDLE is on exactly one of its lines.
expect_warnings() {
    want=$1
    needles=$2
    shift 2
    run "$@"
    bad=
    [ "$rc" -eq "$want" ] || bad="$bad exit $rc (expected $want);"
    grep -qv '^springsim: ' "$err" && bad="$bad a line not starting 'springsim: ';"
    old_ifs=$IFS
    IFS='
'
    for needle in $needles; do
        c=$(grep -cF -- "$needle" "$err")
        [ "$c" -eq 1 ] || bad="$bad \"$needle\" on $c lines (expected 1);"
    done
    IFS=$old_ifs
    if [ -n "$bad" ]; then fail "$cmd:$bad stderr: $(show "$err")"; else pass; fi
}
# issue 10's damped instabilities: warned before the run, which then stops (exit 1)
expect_warnings 1 "springsim: warning: dt = 0.05 s is unstable with rk4 for these springs and dampers: dt < 0.0279 s is stable
blew up" --headless -n 1 --damping 100 --dt 0.05 --no-collisions --duration 2
case $(first_line "$err") in
"springsim: warning: dt = 0.05 s is unstable"*) pass ;;
*) fail "$cmd: the warning should come first; stderr: $(show "$err")" ;;
esac
expect_warnings 1 "springsim: warning: dt = 0.05 s is unstable with rk4 for these springs and dampers: dt < 0.0485 s is stable" \
    -n 1 --boundary wall --spring 1458 --damping 54 --x0 0.01 --dt 0.05 --headless
# the same chain at a stable dt runs without a word; exact has no limit
expect_ok -n 1 --boundary wall --spring 1458 --damping 54 --x0 0.01 --dt 0.01 --headless
expect_warnings 1 "springsim: warning: dt = 0.03 s is unstable with euler" --headless -n 1 \
    --damping 100 --dt 0.03 --no-collisions --duration 2 --integrator euler
expect_ok --headless -n 1 --damping 100 --dt 0.05 --no-collisions --duration 2 --integrator exact
# accuracy: the N = 10 chain loses its top mode to rk4's damping; a 23.7 Hz drive
expect_warnings 0 "springsim: warning: dt = 0.05 s is accurate only roughly: within a period the highest mode (7.05 Hz) is off by up to 82 % of its size with rk4 (a period loses 76 % and leads 31°); dt < 0.0148 s keeps it under 1 %" \
    --headless -n 10 --spring 50 --mass 0.1 --damping 0 --dt 0.05 --duration 1
expect_equal "$cmd: lines on stderr" 1 "$(lines "$err")"
check_csv "$out" "$cmd"
expect_warnings 0 "springsim: warning: dt = 0.05 s is accurate only roughly: the steady motion at the 23.7 Hz drive's frequency is off by 1183 % with rk4 (0.84 steps per period); dt < 0.0113 s keeps it under 1 %" \
    --headless --frequency 23.7 --dt 0.05 --duration 1
expect_equal "$cmd: lines on stderr" 1 "$(lines "$err")"
# issue 17: semi-implicit and verlet with dampers not proportional to the masses, past
# the limit of their own one-step matrices: warned, and stopped where they blow up
expect_warnings 1 "springsim: warning: dt = 0.04 s is unstable with semi-implicit for these springs and dampers: dt < 0.0333 s is stable
blew up at t = 0.2 s (the energy passed 10 times what it could be)" --headless -n 2 --mass 2,0.1 --spring 10,50,10 --damping 10,5 --boundary wall \
    --integrator semi-implicit --dt 0.04 --x0=0.01,0 --duration 2
expect_warnings 1 "springsim: warning: dt = 0.05 s is unstable with verlet for these springs and dampers: dt < 0.0447 s is stable
blew up" --headless -n 2 --mass 0.1 --spring 100,50,100 --damping 20,0 --boundary wall \
    --integrator verlet --dt 0.05 --x0=0,0.01 --duration 3
# just inside it: runs to the end, with only the accuracy it has said
expect_warnings 0 "springsim: warning: dt = 0.044 s is accurate only roughly: within a period the highest mode (6.17 Hz) is off by up to 185 %" \
    --headless -n 2 --mass 0.1 --spring 100,50,100 --damping 20,0 --boundary wall \
    --integrator verlet --dt 0.044 --x0=0,0.01 --duration 3
expect_equal "$cmd: lines on stderr" 1 "$(lines "$err")"
# semi-implicit keeps the amplitude but not the phase: at w dt = 1.9, flagged
expect_warnings 0 "springsim: warning: dt = 0.05 s is accurate only roughly: within a period the highest mode (6.05 Hz) is off by up to 649 % of its size with semi-implicit (a period keeps its amplitude and leads 115°); dt < 0.000521 s keeps it under 1 %" \
    --headless -n 1 --mass 0.05 --spring 36.1 --damping 0 --boundary wall --x0=0.1 \
    --no-collisions --dt 0.05 --integrator semi-implicit --duration 1
# a 2 Hz drive at 10 steps a period: exact follows it exactly and rk4 to 0.04 %, no
# word; verlet's steady motion is 3.9 % off (and its lowest mode 2.4 % within a period)
expect_ok --headless --frequency 2 --dt 0.05 --integrator exact --duration 1
expect_ok --headless --frequency 2 --dt 0.05 --integrator rk4 --duration 1
expect_warnings 0 "the steady motion at the 2 Hz drive's frequency is off by 3.9 % with verlet (10 steps per period); dt < 0.0255 s keeps it under 1 %" \
    --headless --frequency 2 --dt 0.05 --integrator verlet --duration 1
# the velocity cap: one line at the end with the count and the first time
expect_warnings 0 "springsim: warning: the velocity cap (50 m/s) acted 46 times, first at t = 0.014 s; the energy balance includes what it removed" \
    --headless -n 1 --spring 1000 --damping 0 --x0 2 --no-collisions --dt 0.001 --duration 2 --energy \
    --amplitude 1
expect_equal "$cmd: lines on stderr" 1 "$(lines "$err")"
check_csv "$out" "$cmd"
# the contact column holds what the cap took: 0 at the start, more than 0 at the end
expect_equal "$cmd: contact at t = 0" 0 "$(column "$out" contact 1)"
last=$(column "$out" contact 2001)
if awk -v c="$last" 'BEGIN { exit !(c > 0) }'; then pass; else
    fail "$cmd: contact at the end is '$last', expected more than 0"
fi

# 11. Inputs the fuzzers once crashed on (tests/fuzz/regressions/preset-*): each is now
# a clean one-line error with exit 2.
for f in "$(dirname "$0")"/fuzz/regressions/preset-*; do
    [ -f "$f" ] || continue
    expect_one_line_error 2 "$f:" -p "$f" --modes
done

# 10. The man page's KEYS section lists exactly the key table the program uses (the
# help overlay is drawn from the same table): each `--keys` line, spelled in roff.
man=$(dirname "$0")/../man/springsim.1
if expect_ok --keys; then
    [ "$(lines "$out")" -ge 8 ] && pass || fail "$cmd: expected the key table, got: $(show "$out")"
    keys_in_man=$(sed -n '/^\.SH KEYS/,/^\.SH /p' "$man" | awk '/^\.TP/ { getline k; getline h;
        sub(/^\.B /, "", k); print k "\t" h }' | sed 's/\\-/-/g; s/\\e/\\/g')
    want=$(sed 's/↑/\\(ua/g; s/↓/\\(da/g; s/←/\\(<-/g; s/→/\\(->/g' "$out")
    if [ "$keys_in_man" = "$want" ]; then pass; else
        fail "man page KEYS differ from --keys: $(printf '%s\n' "$keys_in_man" | head -c 200 | tr '\n' '|') vs $(printf '%s\n' "$want" | head -c 200 | tr '\n' '|')"
    fi
fi

# The tuned-mass damper (Den Hartog's optimum, mu = 0.05): the primary's two peaks each
# within 3 % of sqrt(1 + 2/mu) times the static deflection F/k1 = 0.05 m, and of each
# other; with the absorber's damper at 0, the primary at its own frequency 0.5033 Hz
# moves at least 100 times less than it would alone (undamped there: without bound, so
# the alone figure is taken with a tiny damper, 1e-3 N s/m, which the absorber beats).
if expect_ok -p tuned-mass-damper --sweep 0.3:0.7:4001; then
    peaks=$(awk -F, 'NR > 1 { a = $2; if (NR > 3 && pa > ppa && pa > a) printf "%s ", pa; ppa = pa; pa = a }' "$out")
    verdict=$(echo "$peaks" | awk '{ want = 0.05 * sqrt(41); ok = NF == 2;
        for (i = 1; i <= NF; i++) if ($i < 0.97 * want || $i > 1.03 * want) ok = 0;
        if (NF == 2 && ($1 > 1.03 * $2 || $2 > 1.03 * $1)) ok = 0; print ok ? "ok" : "bad" }')
    expect_equal "tuned-mass-damper: two equal peaks near sqrt(41) x 0.05 m ($peaks)" ok "$verdict"
fi
if expect_ok -p tuned-mass-damper --spring-damping 0 --sweep 0.5032921210:0.6:2; then
    with=$(awk -F, 'NR == 2 { print $2 }' "$out")
    if expect_ok -p tuned-mass-damper -n 1 --mass 1 --spring 10,0 --spring-damping 0 \
        --damping 0.001 --sweep 0.5032921210:0.6:2; then
        alone=$(awk -F, 'NR == 2 { print $2 }' "$out")
        expect_equal "undamped absorber: $with m against $alone m alone" ok \
            "$(awk -v a="$with" -v b="$alone" 'BEGIN { print a * 100 <= b ? "ok" : "bad" }')"
    fi
fi

# --modes on the half-damped chain at N = 300 (the left half's masses damped by 2 N s/m,
# walls at both ends): the damped eigenproblem of 600 states in under 2 s of processor
# time, every mode with its damping ratio (N = 1000, under 60 s, in tests/long/modes.sh).
d300=$(awk 'BEGIN { for (i = 1; i <= 300; i++) printf "%s%s", (i > 1 ? "," : ""), (i <= 150 ? 2 : 0) }')
/usr/bin/time -f '%U %S' -o "$tmp/time" "$SPRINGSIM" --modes -n 300 --spring 10 --boundary wall \
    --damping "$d300" >"$out" 2>"$err"
rc=$?
secs=$(tail -n 1 "$tmp/time" | awk '{ print $1 + $2 }')
rows=$(awk -F, 'NR > 1 && $2 > 0 && $4 != "" { k++ } END { print k + 0 }' "$out")
if [ "$rc" -eq 0 ] && [ "$rows" -eq 300 ] && awk -v s="$secs" 'BEGIN { exit !(s > 0 && s < 2) }'; then
    pass
else
    fail "--modes -n 300 half-damped: expected 300 modes with a ratio in under 2 s; exit $rc, $rows modes, $secs s: $(show "$err")"
fi

echo "cli: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
