#!/bin/sh
# tests/cli-files.sh: end-to-end tests of the real binary's command line (springsim(1)):
# -o written whole or not at all, presets and preset files, --help and --version, a large
# --modes run. The rest of the command line is in tests/cli.sh.
# Run from the repository root as `sh tests/cli-files.sh`, with SPRINGSIM naming the binary
# (default ./springsim). Prints one line per failing case, then exactly one summary line
# "cli-files: N passed, M failed"; exits non-zero if anything failed.

NAME=cli-files
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/cli.sh"
trap 'exit 1' HUP INT TERM

# Keep the user's own presets out of the way: an empty user preset directory, no
# $SPRINGSIM_PRESETS. Cases that need them set them for one run.
plain_env

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
# the same key through its other spelling ('_' for '-') is given twice too
printf '[system]\nmasses = 2\nspring-cubic = 1\nspring_cubic = 2\n' >"$tmp/alias.ini"
expect_one_line_error 2 "alias.ini:4:
'spring_cubic' is given twice (first on line 3, as 'spring-cubic')" -p "$tmp/alias.ini" --modes
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
# walls at both ends): the damped eigenproblem of 600 states, every mode with its damping
# ratio. (Its time, under 2 s of processor time, is make bench's to print: a timed test
# fails on a busy machine. N = 1000 is in tests/long/modes.sh.)
d300=$(awk 'BEGIN { for (i = 1; i <= 300; i++) printf "%s%s", (i > 1 ? "," : ""), (i <= 150 ? 2 : 0) }')
"$SPRINGSIM" --modes -n 300 --spring 10 --boundary wall --damping "$d300" >"$out" 2>"$err"
rc=$?
rows=$(awk -F, 'NR > 1 && $2 > 0 && $4 != "" { k++ } END { print k + 0 }' "$out")
if [ "$rc" -eq 0 ] && [ "$rows" -eq 300 ]; then
    pass
else
    fail "--modes -n 300 half-damped: expected 300 modes with a ratio; exit $rc, $rows modes: $(show "$err")"
fi

echo "cli-files: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
