#!/bin/sh
# tests/nonlinear.sh: the command line of chains with cubic springs: exact refused, the
# sweep by harmonic balance (its columns, branches, stability and folds), the simulated
# sweep up and down, the linear sweep's output unchanged, the preset key written either
# way. Run from the repository root; SPRINGSIM names the binary (default ./springsim).
NAME=nonlinear
. "$(dirname "$0")/lib/check.sh"
plain_env

# one_error STATUS NEEDLE ARGS...: exit STATUS, one line on stderr naming NEEDLE, no stdout.
one_error() {
    want=$1 needle=$2
    shift 2
    run "$@"
    if [ "$rc" -eq "$want" ] && [ ! -s "$out" ] && [ "$(wc -l <"$err")" -eq 1 ] &&
        grep -q "^springsim: .*$needle" "$err"; then pass; else
        fail "$cmd: exit $rc, stderr: $(head -c 300 "$err")"
    fi
}

one_error 2 "exact.*nonlinear.*rk4" --integrator exact --spring-cubic 0,5,0 --headless
one_error 2 "exact.*nonlinear" -n 1 --integrator exact --spring-cubic 3 --sweep 0.5:1:3
one_error 2 "spring-cubic.*2 values for 3 springs" --spring-cubic 1,2 --headless
one_error 2 "sweep-run.*'sideways' is not a direction" --sweep-run sideways 0.5:1:3
one_error 2 "sweep-run.*needs up or down" --sweep-run up
one_error 2 "sweep-run.*out of range" --sweep-run up 1:0.5:3
one_error 2 "figure.*cubic" --spring-cubic 1 --sweep 0.5:1:3 --figure "$tmp/f.png"

# The linear sweep keeps its columns; a cubic one gains branch and stable.
run -n 2 --sweep 0.5:1:3
[ "$(sed -n 1p "$out")" = "frequency_hz,amp1,amp2,phase1,phase2" ] && pass ||
    fail "linear --sweep header: $(sed -n 1p "$out")"
run -p duffing --sweep 0.8:0.9:2 --meta
if [ "$rc" -eq 0 ] && grep -qx "frequency_hz,branch,stable,amp1,phase1" "$out" &&
    [ "$(grep -c '^0.8,' "$out")" -eq 3 ] && grep -q '^0.8,2,0,' "$out" &&
    grep -q '^0.8,1,1,' "$out" && grep -q '^0.8,3,1,' "$out" && [ "$(grep -c '^0.9,' "$out")" -eq 1 ] &&
    [ "$(grep -c '^# fold [12]: 0\.[78][0-9]* Hz' "$out")" -eq 2 ]; then pass; else
    fail "duffing --sweep: three branches at 0.8 Hz, the middle unstable, two folds: $(head -c 600 "$out" | tr '\n' '|')"
fi
# The folds from --meta, each between two neighbouring frequencies of the sweep.
up=$(sed -n 's/^# fold 1: \([0-9.]*\) Hz.*/\1/p' "$out")
low=$(sed -n 's/^# fold 2: \([0-9.]*\) Hz.*/\1/p' "$out")

# The same oscillator driven by the force input (a wall at the right, F = k_N A = 2.5 N on
# the mass) with 0.2 of its 0.3 N s/m beside the wall's spring: the same equation, so the
# same folds (1e-6), the middle branch unstable.
run -n 1 --boundary wall --force 2.5 --spring-cubic 4,0 --damping 0.1 --spring-damping 0.2,0 \
    --sweep 0.8:0.9:2 --meta
fup=$(sed -n 's/^# fold 1: \([0-9.]*\) Hz.*/\1/p' "$out")
flow=$(sed -n 's/^# fold 2: \([0-9.]*\) Hz.*/\1/p' "$out")
if [ "$rc" -eq 0 ] && grep -q '^0.8,2,0,' "$out" && awk -v a="$up" -v b="$fup" -v c="$low" \
    -v d="$flow" 'BEGIN { exit !(b > 0 && d > 0 && (a - b) ^ 2 < 1e-12 * a * a &&
                                  (c - d) ^ 2 < 1e-12 * c * c) }'; then pass; else
    fail "forced --sweep: folds $fup, $flow (the motor's $up, $low): $(head -c 400 "$err")"
fi
one_error 2 "does not drive the chain.*no force" -n 1 --boundary wall --spring-cubic 4 \
    --sweep 0.5:1:3

# A simulated sweep up drops just above the upper fold; down it jumps just below the lower.
run -p duffing --sweep-run up 0.78:0.85:71
if [ "$rc" -eq 0 ] && awk -F, -v fold="$up" 'NR > 1 && $2 == "" {
        if (!drop && prev && $4 < 0.5 * prev) { drop = $1 }
        prev = $4
    } END { exit !(drop > fold && drop <= 1.005 * fold) }' "$out"; then pass; else
    fail "sweep-run up: no drop within 0.5 % above $up Hz: $(tr '\n' '|' <"$out" | head -c 400)"
fi
run -p duffing --sweep-run down 0.78:0.85:71
if [ "$rc" -eq 0 ] && awk -F, -v fold="$low" 'NR > 1 {
        if (prev && $4 > 1.5 * prev && !rise) { rise = $1 }
        prev = $4
    } END { exit !(rise < fold && rise >= 0.995 * fold) }' "$out"; then pass; else
    fail "sweep-run down: no rise within 0.5 % below $low Hz: $(tr '\n' '|' <"$out" | head -c 400)"
fi

# A square drive: harmonic balance says it is for a sine, and sweeps by simulation.
run -p duffing --wave square --sweep 0.5:0.6:2
if [ "$rc" -eq 0 ] && grep -q "harmonic balance is for a sine drive" "$err" &&
    [ "$(grep -c '^0\.[56],,1,' "$out")" -eq 2 ]; then pass; else
    fail "square --sweep: $(head -c 300 "$err") $(tr '\n' '|' <"$out")"
fi

# The preset key reads as spring_cubic or spring-cubic; --meta writes it only when used.
printf '[system]\nmasses = 1\nspring_cubic = 5, 0\n' >"$tmp/a.ini"
printf '[system]\nmasses = 1\nspring-cubic = 5, 0\n' >"$tmp/b.ini"
run -p "$tmp/a.ini" --headless --duration 0.01 --meta
a=$(sed -n 2p "$out")
run -p "$tmp/b.ini" --headless --duration 0.01 --meta
b=$(sed -n 2p "$out")
case $a in *"--spring-cubic 5,0 "*) [ "$a" = "$b" ] && pass || fail "presets differ: $a / $b" ;;
*) fail "spring_cubic not read: $a" ;; esac
run --headless --duration 0.01 --meta
case $(sed -n 2p "$out") in *spring-cubic*) fail "a linear chain's --meta names spring-cubic" ;; *) pass ;; esac

# The plain mode: set spring-cubic changes the chain (its modes say linearised), and the
# exact integrator is then refused with the reason.
printf 'set spring-cubic 0,5\nmodes\nset integrator exact\nquit\n' >"$tmp/in"
timeout 30 "$SPRINGSIM" --plain -n 1 <"$tmp/in" >"$out" 2>&1
if grep -q '^ok modes (linearised at rest):' "$out" &&
    grep -q "^error integrator: 'exact' steps a linear chain.*nonlinear" "$out"; then pass; else
    fail "plain set spring-cubic: $(tr '\n' '|' <"$out" | head -c 500)"
fi

# A simulated sweep of a linear chain settles to the steady state the linear theory
# gives, each amplitude within 0.1 % (the point is steady to 0.1 %), also where a drive
# period is no whole number of steps (0.3 to 2 Hz at dt 0.01).
run -n 2 --damping 0.3 --sweep-run up 0.3:2:18
"$SPRINGSIM" -n 2 --damping 0.3 --sweep 0.3:2:18 >"$tmp/theory.csv"
worst=$(paste -d, "$out" "$tmp/theory.csv" | awk -F, 'NR > 1 { for (i = 4; i <= 5; i++) {
        e = ($i - $(i + 5)) / $(i + 5); e = e < 0 ? -e : e; if (e > w) w = e } }
    END { print w + 0 }')
if [ "$rc" -eq 0 ] && [ "$(wc -l <"$out")" -eq 19 ] &&
    awk -v w="$worst" 'BEGIN { exit !(w <= 1e-3) }'; then pass; else
    fail "sweep-run of a linear chain: worst amplitude $worst of the theory's (at most 1e-3)"
fi

# The linear theory says it is the linearised chain's wherever a cubic chain meets it: a
# stability warning at a dt past the limit (headless, and plain after set dt), --modes.
run -n 1 --spring 2000 --spring-cubic 10 --headless --dt 0.05 --duration 0.1
if grep -q 'warning: .*linearised at rest: large swings stiffen' "$err"; then pass; else
    fail "headless past the limit with a hardening spring: no linearised note: $(head -c 300 "$err")"
fi
run -p duffing --modes
if [ "$rc" -eq 0 ] && grep -q 'note: the modes of the chain linearised at rest' "$err"; then pass; else
    fail "--modes of a cubic chain: no linearised note: $(head -c 300 "$err")"
fi
printf 'set dt 0.05\nquit\n' | "$SPRINGSIM" --plain -n 1 --spring 2000 --spring-cubic 10 >"$out" 2>&1
if grep -q 'linearised at rest: large swings stiffen' "$out"; then pass; else
    fail "plain set dt past the limit with a hardening spring: no linearised note: $(grep -i 'warn\|limit' "$out" | head -c 300)"
fi

# --sweep-run never calls a runaway steady: a softening spring pulled past its turnover
# (the state once froze at 9e69 m, every row stable), a dt past the stability limit (the
# velocity cap kept it finite: 0.0517 m "steady"), a drive too fast for the step (0.05
# steps a period measured 1.2e-13 m at -90 degrees). No row is written for them.
one_error 2 "sweep-run: 2000 Hz is 0.05 steps a period.*up to 50 Hz" -p duffing \
    --sweep-run up 1000:2000:2
run -n 1 --spring-cubic -10 --amplitude 1 --sweep-run up 0.2:1:5 --no-collisions
if [ "$rc" -eq 1 ] && [ "$(wc -l <"$out")" -eq 1 ] &&
    grep -q "^springsim: --sweep-run: the motion ran away at 0.2 Hz (spring 1 softens" "$err"; then
    pass
else
    fail "$cmd: exit $rc, rows $(tr '\n' '|' <"$out" | head -c 200), stderr: $(head -c 300 "$err")"
fi
run -n 1 --spring 2000 --damping 0.1 --dt 0.05 --no-collisions --sweep-run up 0.5:1:2
if [ "$rc" -eq 1 ] && [ "$(wc -l <"$out")" -eq 1 ] &&
    grep -q "^springsim: warning: dt = 0.05 s is unstable with rk4" "$err" &&
    grep -q "^springsim: --sweep-run: the simulation blew up at 0.5 Hz" "$err"; then
    pass
else
    fail "$cmd: exit $rc, rows $(tr '\n' '|' <"$out" | head -c 200), stderr: $(head -c 300 "$err")"
fi

# A square, triangle or sawtooth drive: the linear --sweep gives the response to the
# waveform's fundamental (it once gave the sine's, 4/pi too small for a square), the first
# harmonic the simulated sweep measures: a k3 of 1e-12 (simulated) agrees within 0.1 %.
for w in square triangle sawtooth; do
    run -n 1 --wave $w --sweep 0.2:0.6:3
    cp "$out" "$tmp/lin-$w.csv"
    run -n 1 --wave $w --spring-cubic 1e-12 --sweep 0.2:0.6:3
    worst=$(awk -F, 'NR == FNR { if (FNR > 1) a[FNR] = $2; next }
        FNR > 1 { d = $4 / a[FNR] - 1; if (d < 0) d = -d; if (d > m) m = d }
        END { printf "%.2e", m + 0 }' "$tmp/lin-$w.csv" "$out")
    if awk -v w="$worst" 'BEGIN { exit !(w < 1e-3) }' && [ "$(wc -l <"$out")" -eq 4 ]; then
        pass
    else
        fail "--wave $w --sweep: linear against simulated first harmonic off by $worst (at most 1e-3): $(tr '\n' '|' <"$tmp/lin-$w.csv")"
    fi
done

# A softening spring: --headless says so before the run, and a start past its turnover
# runs away for the physics' reason, not dt's (it was "blew up ... with dt = 0.01 s and
# rk4", dt well inside the limit).
run -n 1 --spring-cubic -10 --x0 2 --amplitude 0 --no-collisions --headless
if [ "$rc" -eq 1 ] &&
    grep -q "^springsim: warning: spring 1 (wall[^)]*1) softens: its force turns over at a stretch of 0.577 m" "$err" &&
    grep -q "^springsim: the simulation blew up at t = .*: spring 1 (wall[^)]*1) softens, and past a stretch of 0.577 m" "$err" &&
    ! grep -q "with dt = " "$err"; then
    pass
else
    fail "$cmd: exit $rc, stderr: $(head -c 400 "$err")"
fi

# Undamped, a steady motion is a centre (neutrally stable): stable 1, not a rounding's
# sign (every row of an undamped duffing was 0, the nearly linear 0.5 Hz one too).
run -p duffing --damping 0 --sweep 0.5:1.5:11
if [ "$rc" -eq 0 ] && [ "$(awk -F, 'NR > 1 && $3 != 1' "$out" | wc -l)" -eq 0 ] &&
    [ "$(wc -l <"$out")" -eq 12 ]; then
    pass
else
    fail "$cmd: expected 11 rows, each stable 1: $(tr '\n' '|' <"$out" | head -c 400)"
fi

# --sweep-run takes any drive --sweep takes: a square motor (which --sweep of a cubic
# chain sweeps by simulation), a force with the end free (the tuned-mass damper: the
# linear --sweep's values within 0.1 %); nothing driving is refused.
run -p duffing --wave square --sweep-run up 0.7:0.9:3
expect_rows() {
    if [ "$rc" -eq 0 ] && [ "$(wc -l <"$out")" -eq "$1" ]; then pass; else
        fail "$cmd: exit $rc, $(wc -l <"$out") lines (expected $1): $(head -c 300 "$err")"
    fi
}
expect_rows 4
run -p tuned-mass-damper --sweep 0.3:0.7:5
cp "$out" "$tmp/tmd-lin.csv"
run -p tuned-mass-damper --sweep-run up 0.3:0.7:5
expect_rows 6
worst=$(awk -F, 'NR == FNR { if (FNR > 1) { a[FNR] = $2; b[FNR] = $3 } next }
    FNR > 1 { for (k = 0; k < 2; k++) { d = $(4 + k) / (k ? b[FNR] : a[FNR]) - 1
        if (d < 0) d = -d; if (d > m) m = d } }
    END { printf "%.2e", m + 0 }' "$tmp/tmd-lin.csv" "$out")
if awk -v w="$worst" 'BEGIN { exit !(w < 1e-3) }'; then pass; else
    fail "--sweep-run of the tuned-mass damper: off the linear sweep by $worst (at most 1e-3)"
fi
one_error 2 "sweep-run: nothing drives the chain" --amplitude 0 --sweep-run up 0.3:0.7:5

# Just past the upper fold (0.8365 Hz) nothing stays high: the motion lingers near the
# fold's ghost before it falls, and the point once took that slow drift for steady
# (1.577 m at 0.84 Hz; the run from there falls to 0.3246 m, as the jump lesson says).
run -p duffing --sweep-run up 0.5:0.84:35
last=$(tail -n 1 "$out" | cut -d, -f4)
if [ "$rc" -eq 0 ] && awk -v a="$last" 'BEGIN { exit !(a > 0.3 && a < 0.35) }'; then pass; else
    fail "$cmd: at 0.84 Hz expected the low branch (about 0.3245 m), got '$last'"
fi

summary
