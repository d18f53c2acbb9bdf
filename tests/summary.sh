#!/bin/sh
# tests/summary.sh: --summary end to end (issue 13): a single undamped mass's closed forms,
# the dampers' books against the energy lost, the contacts against a count from the
# --headless time series of the same run, -o and the errors (the README's study, which
# runs through --batch, is tests/batch.sh's).
# Prints one line per failing case, then "summary: N passed, M failed".

NAME=summary
. "$(dirname "$0")/lib/check.sh"
trap 'exit 1' HUP INT TERM
plain_env


# col NAME [FILE]: the value of column NAME in the row of a summary (quoted lists, which
# hold commas, blanked first).
col() {
    sed 's/"[^"]*"/L/g' "${2:-$out}" | awk -F, -v name="$1" '
        NR == 1 { for (i = 1; i <= NF; i++) if ($i == name) c = i; next }
        NR == 2 && c { print $c }'
}

# near WHAT GOT WANT TOL: |GOT - WANT| <= TOL.
near() {
    if awk -v g="$2" -v w="$3" -v t="$4" 'BEGIN { d = g - w; exit !(g != "" && d <= t && -d <= t) }'
    then pass; else fail "$1: got '$2', expected $3 within $4"; fi
}

# ok: the last run exited 0, quietly, with a header and one row.
ok() {
    if [ "$rc" -eq 0 ] && ! [ -s "$err" ] && [ "$(awk 'END { print NR }' "$out")" = 2 ]; then
        pass
        return 0
    fi
    fail "$cmd: exit $rc, $(awk 'END { print NR }' "$out") lines, stderr: $(head -c 200 "$err")"
    return 1
}

# usage_error NEEDLE... -- ARGS...: exit 2, one line on stderr naming each NEEDLE, no output.
usage_error() {
    needles=
    while [ "$1" != -- ]; do needles="$needles $1"; shift; done
    shift
    run "$@"
    bad=
    [ "$rc" -eq 2 ] || bad="$bad exit $rc;"
    [ -s "$out" ] && bad="$bad output on stdout;"
    [ "$(awk 'END { print NR }' "$err")" = 1 ] || bad="$bad not one line on stderr;"
    for n in $needles; do grep -qe "$n" "$err" || bad="$bad does not name $n;"; done
    if [ -z "$bad" ]; then pass; else fail "$cmd:$bad $(head -c 200 "$err")"; fi
}

# A single undamped mass between two 10 N/m springs, from x0 = -0.5 at rest: w = sqrt(20),
# 1000 steps a period, 6 periods, so the rms is taken over 3 whole periods. Closed forms:
# max |x| = 0.5 (the start), rms x = 0.5/sqrt(2), max |v| = 0.5 w; nothing dissipated,
# no work, no contact.
dt=$(awk 'BEGIN { printf "%.17g", 2 * atan2(0, -1) / sqrt(20) / 1000 }')
T=$(awk -v dt="$dt" 'BEGIN { printf "%.17g", 6000 * dt }')
run --summary -n 1 --boundary wall --damping 0 --x0 -0.5 --dt "$dt" --duration "$T"
if ok; then
    near "max_abs_x1" "$(col max_abs_x1)" 0.5 0
    near "rms_x1" "$(col rms_x1)" "$(awk 'BEGIN { printf "%.17g", 0.5 / sqrt(2) }')" 1e-9
    near "max_abs_v1" "$(col max_abs_v1)" "$(awk 'BEGIN { printf "%.17g", 0.5 * sqrt(20) }')" 1e-9
    near "contacts" "$(col contacts)" 0 0
    near "dissipated" "$(col dissipated)" 0 0
    near "motor_work" "$(col motor_work)" 0 0
fi

# A force on mass 1 and spring dampers (the tuned-mass damper, run for 20 s): the
# settings are in the row as the options spell them, and the books are --energy's last
# row: force_work and dissipated the same, motor_work 0.
set -- -p tuned-mass-damper --duration 20
run --summary "$@"
if ok; then
    near "boundary is a setting" "$([ "$(col boundary)" = free ] && echo 1)" 1 0
    near "force" "$(col force)" 0.5 0
    near "force-on" "$(col force-on)" 1 0
    last=$("$SPRINGSIM" --headless --energy "$@" | awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i }
        END { printf "%.12g %.12g", $c["force_work"], $c["dissipated"] }')
    near "force_work as --energy has it" "$(col force_work)" "${last% *}" 1e-11
    near "dissipated as --energy has it" "$(col dissipated)" "${last#* }" 1e-11
    near "no motor work with the motor off" "$(col motor_work)" 0 0
fi

# Damping and no drive: the dampers took what the mechanical energy lost, E0 - E(T), with
# E(T) from the last row of the same run's time series (1/2 m v^2 + 2 * 1/2 k x^2).
set -- -n 1 --boundary wall --damping 0.7 --x0 0.5 --v0 1.5 --no-collisions --dt 0.001 --duration 5
run --summary "$@"
if ok; then
    lost=$("$SPRINGSIM" --headless "$@" | awk -F, 'END { printf "%.17g", 0.5 * 1.5 ^ 2 + 10 * 0.5 ^ 2 - (0.5 * $3 ^ 2 + 10 * $2 ^ 2) }')
    near "dissipated against the energy lost" "$(col dissipated)" "$lost" 1e-8
    near "no work without a drive" "$(col motor_work)" 0 0
    # The peaks over the whole series and the rms over its rows with t > T/2 (2.5 s),
    # computed from the time series: the amplitude decays, so the window shows.
    "$SPRINGSIM" --headless "$@" | awk -F, 'NR > 1 {
            if ($2 * $2 > xx) xx = $2 * $2
            if ($3 * $3 > vv) vv = $3 * $3
            if ($1 > 2.5) { s += $2 * $2; n++ } }
        END { printf "%.17g %.17g %.17g\n", sqrt(xx), sqrt(s / n), sqrt(vv) }' >"$tmp/series"
    read -r mx rms mv <"$tmp/series"
    near "max_abs_x1 against the series" "$(col max_abs_x1)" "$mx" 1e-11
    near "rms_x1 over the last half of the series" "$(col rms_x1)" "$rms" 1e-11
    near "max_abs_v1 against the series" "$(col max_abs_v1)" "$mv" 1e-11
fi

# The collisions preset for 120 s: the contacts are the steps at which the time series'
# contact column (the energy restitution took) went up, in the same run.
run --summary -p collisions --duration 120
if ok; then
    bounces=$("$SPRINGSIM" --headless --energy -p collisions --duration 120 | awk -F, '
        NR == 1 { for (i = 1; i <= NF; i++) if ($i == "contact") c = i; next }
        NR > 2 && $c > last { n++ }
        { last = $c }
        END { print n + 0 }')
    near "contacts against the series ($bounces bounces)" "$(col contacts)" "$bounces" 0
    [ "$bounces" -gt 20 ] && pass || fail "the collisions preset bounced only $bounces times"
    cp "$out" "$tmp/collisions.csv"
fi

# -o: the same two lines in the file, nothing on standard output, no temporary left.
run --summary -p collisions --duration 120 -o "$tmp/study.csv"
if [ "$rc" -eq 0 ] && ! [ -s "$out" ] && cmp -s "$tmp/study.csv" "$tmp/collisions.csv" &&
    [ "$(ls "$tmp" | grep -c tmp)" = 0 ]; then
    pass
else
    fail "$cmd: exit $rc, or the file differs from standard output's row"
fi

# --summary is a headless run whether or not --headless is given.
run --headless --summary -p collisions --duration 120
cmp -s "$out" "$tmp/collisions.csv" && pass || fail "$cmd: differs from --summary alone"

# --meta: its '#' lines first, then the same two lines; the command line it gives repeats
# the row.
run --summary --meta -p collisions --duration 120
again=$(sed -n 's/^# springsim --summary /--summary /p' "$out")
grep -v '^#' "$out" >"$tmp/meta-row"
if [ "$rc" -eq 0 ] && [ "$(cut -c1 "$out" | head -n 2)" = "$(printf '#\n#')" ] &&
    cmp -s "$tmp/meta-row" "$tmp/collisions.csv" && [ -n "$again" ] &&
    (set -f; "$SPRINGSIM" $again | cmp -s - "$tmp/collisions.csv"); then
    pass
else
    fail "$cmd: not the '#' lines then the row, or '$again' does not repeat it"
fi

# The default chain (no option but the frequency) driven at either natural frequency
# (--modes) makes no contact in 60 s: the default amplitude lets a class find resonance.
# The swings are large all the same (over five times the drive's): resonance, not a
# drive too weak to see.
"$SPRINGSIM" --modes >"$tmp/modes.csv" 2>"$err"
nat=$(awk -F, 'NR > 1 { print $2 }' "$tmp/modes.csv")
if [ "$(echo "$nat" | wc -w)" = 2 ]; then pass; else fail "--modes of the default chain: $(show "$tmp/modes.csv")"; fi
for f in $nat; do
    run --summary --frequency "$f" --duration 60
    if ok; then
        near "contacts at the default amplitude, driven at $f Hz" "$(col contacts)" 0 0
        amp=$(col amplitude) x=$(col max_abs_x1)
        if awk -v a="$amp" -v x="$x" 'BEGIN { exit !(a > 0 && x > 5 * a) }'; then pass; else
            fail "$cmd: max |x1| = $x m at amplitude $amp m: not a resonance"
        fi
    fi
done

usage_error --summary --modes -- --summary --modes
usage_error --summary --sweep -- --sweep 0.1:1:3 --summary
usage_error --summary --list-presets -- --list-presets --summary
usage_error --summary -- --summary=yes

# A run that blows up writes no row and exits 1.
run --summary --integrator euler --dt 0.05 --spring 1000 --no-collisions --duration 100
if [ "$rc" -eq 1 ] && ! [ -s "$out" ] && grep -q 'blew up' "$err"; then pass; else
    fail "$cmd: exit $rc (expected 1), stdout $(wc -c <"$out") bytes (expected none)"
fi

summary
