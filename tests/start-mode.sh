#!/bin/sh
# tests/start-mode.sh: --start-mode K[:AMP] and the preset key start-mode (issue 12): its
# errors (one line, exit 2, FILE:LINE in a preset), the start it gives against --modes'
# shapes, how it combines with --x0, --v0 and --random (the later wins), and an undamped
# chain started in mode 2 staying in it. Run from the repository root as
# `sh tests/start-mode.sh`, SPRINGSIM naming the binary (default ./springsim). Ends with
# "start-mode: N passed, M failed".
NAME=start-mode
. "$(dirname "$0")/lib/check.sh"

plain_env

# refused TEXT ARGS...: exit 2, nothing on stdout, one line on stderr starting
# "springsim: " and containing TEXT.
refused() {
    want=$1
    shift
    run "$@"
    n=$(awk 'END { print NR }' "$err")
    line=$(sed -n 1p "$err")
    case $line in
    "springsim: "*"$want"*) ok=1 ;;
    *) ok= ;;
    esac
    if [ "$rc" -eq 2 ] && [ ! -s "$out" ] && [ "$n" -eq 1 ] && [ -n "$ok" ]; then pass; else
        fail "$cmd: expected exit 2 and one line with \"$want\", got exit $rc, $n lines: $(head -c 300 "$err" | tr '\n' '|')"
    fi
}

# accepted ARGS...: exit 0, nothing on stderr.
accepted() {
    run "$@"
    if [ "$rc" -eq 0 ] && [ ! -s "$err" ]; then return 0; fi
    fail "$cmd: expected exit 0 and no message, got exit $rc: $(head -c 300 "$err" | tr '\n' '|')"
    return 1
}

# ---- errors: K from 1 to N, AMP >= 0 and finite, the K[:AMP] form ----
expect="(expected K[:AMP]: a mode 1 <= K <= N, 0 <= AMP <= 10 m, default 0.5)"
refused "--start-mode: '0' is out of range $expect" --headless -n 3 --start-mode 0
refused "--start-mode: '4' is out of range for 3 masses (expected a mode 1 <= K <= 3)" \
    --headless -n 3 --start-mode 4
refused "--start-mode: '-1' is out of range" --headless -n 3 --start-mode -1
refused "--start-mode: '2:-0.5' has amplitude '-0.5', which is out of range $expect" \
    --headless -n 3 --start-mode 2:-0.5
refused "--start-mode: '2:nan' has amplitude 'nan', which is not a finite number" \
    --headless -n 3 --start-mode 2:nan
refused "--start-mode: '2:inf' has amplitude 'inf', which is not a finite number" \
    --headless -n 3 --start-mode 2:inf
refused "--start-mode: '2:abc' has amplitude 'abc', which is not a number" \
    --headless -n 3 --start-mode 2:abc
refused "--start-mode: '2:' has no amplitude after ':'" --headless -n 3 --start-mode 2:
refused "--start-mode: ':0.5' has mode '', which is empty" --headless -n 3 --start-mode :0.5
refused "--start-mode: '2:0.5:1' has amplitude '0.5:1', which is not a number" \
    --headless -n 3 --start-mode 2:0.5:1
refused "--start-mode: 'x:0.5' has mode 'x', which is not a number" \
    --headless -n 3 --start-mode x:0.5
refused "--start-mode: 'abc' is not a number" --headless -n 3 --start-mode abc
refused "--start-mode: '1.5' is not a whole number" --headless -n 3 --start-mode 1.5
refused "--start-mode: '' is empty" --headless -n 3 --start-mode=
refused "--start-mode: '2' is out of range for 1 mass" --modes -n 1 --start-mode 2
# the interactive program checks it before it takes the terminal
refused "--start-mode: '3' is out of range for 2 masses" --start-mode 3
# in a preset: FILE:LINE: key
printf '[system]\nmasses = 3\n[initial]\nstart-mode = 5\n' >"$tmp/five.ini"
refused "five.ini:4: start-mode: '5' is out of range for 3 masses" -p "$tmp/five.ini" --modes
printf '[initial]\n\nstart-mode = 1:-2\n' >"$tmp/neg.ini"
refused "neg.ini:3: start-mode: '1:-2' has amplitude '-2', which is out of range" \
    -p "$tmp/neg.ini" --modes
printf '[system]\nstart-mode = 1\n' >"$tmp/wrong.ini"
refused "wrong.ini:2:" -p "$tmp/wrong.ini" --modes

# ---- the start: AMP times mode K's shape as --modes prints it, at rest ----
# check_start K AMP ARGS...: the first row of --headless is AMP times row K of --modes
# (to 1e-11), velocities 0, the largest |x| = AMP.
check_start() {
    k=$1
    amp=$2
    shift 2
    accepted --modes "$@" || return
    cp "$out" "$tmp/modes.csv"
    if [ "$amp" = default ]; then spec=$k; amp=0.5; else spec=$k:$amp; fi
    accepted --headless --duration 0 --start-mode "$spec" "$@" || return
    bad=$(awk -F, -v k="$k" -v amp="$amp" '
        function abs(x) { return x < 0 ? -x : x }
        NR == FNR { if (FNR == k + 1) for (i = 3; i < NF - 1; i++) phi[i - 2] = $i; next }
        FNR == 2 {
            n = (NF - 2) / 3
            top = 0
            for (i = 1; i <= n; i++) {
                if (abs($(i + 1) - amp * phi[i]) > 1e-11) print "x" i " = " $(i + 1) ", expected " amp * phi[i]
                if ($(i + 1 + n) != 0) print "v" i " = " $(i + 1 + n) ", expected 0"
                if (abs($(i + 1)) > top) top = abs($(i + 1))
            }
            if (abs(top - amp) > 1e-12) print "largest |x| " top ", expected " amp
        }' "$tmp/modes.csv" "$out" | head -n 3 | tr '\n' ';')
    if [ -z "$bad" ]; then pass; else fail "$cmd: $bad"; fi
}
check_start 2 default -n 3 --mass 1,2.5,0.7
check_start 1 0.2 -n 4 --mass 1,2,3,4 --spring 5,10,15,20,25 --boundary free
check_start 3 0 -n 3
check_start 5 1.25 -n 5 --boundary wall

# ---- with the other initial conditions: the later wins ----
first_row() { sed -n 2p "$out"; }
accepted --headless --duration 0 -n 3 --start-mode 2 && mode2=$(first_row)
accepted --headless --duration 0 -n 3 --random --start-mode 2 &&
    { [ "$(first_row)" = "$mode2" ] && pass || fail "$cmd: not mode 2's start: $(first_row)"; }
accepted --headless --duration 0 -n 3 --x0 0.3 --v0 1 --start-mode 2 &&
    { [ "$(first_row)" = "$mode2" ] && pass || fail "$cmd: not mode 2's start: $(first_row)"; }
accepted --headless --duration 0 -n 3 --start-mode 2 --x0 0.3 && x03=$(first_row)
accepted --headless --duration 0 -n 3 --x0 0.3 &&
    { [ "$(first_row)" = "$x03" ] && pass || fail "--start-mode 2 --x0 0.3 should start as --x0 0.3: $x03"; }
accepted --headless --duration 0 -n 3 --start-mode 2 --random --seed 7 && r7=$(first_row)
accepted --headless --duration 0 -n 3 --random --seed 7 &&
    { [ "$(first_row)" = "$r7" ] && pass || fail "--start-mode 2 --random should start as --random: $r7"; }
# a preset's random gives way to --start-mode on the command line, and its start-mode to --x0
printf '[system]\nmasses = 3\n[initial]\nrandom = true\nseed = 7\n' >"$tmp/rand.ini"
accepted --headless --duration 0 -p "$tmp/rand.ini" --start-mode 2 &&
    { [ "$(first_row)" = "$mode2" ] && pass || fail "$cmd: not mode 2's start: $(first_row)"; }
printf '[system]\nmasses = 3\n[initial]\nstart-mode = 2\n' >"$tmp/mode2.ini"
accepted --headless --duration 0 -p "$tmp/mode2.ini" &&
    { [ "$(first_row)" = "$mode2" ] && pass || fail "$cmd: not mode 2's start: $(first_row)"; }
accepted --headless --duration 0 -p "$tmp/mode2.ini" --x0 0.3 &&
    { [ "$(first_row)" = "$x03" ] && pass || fail "$cmd: should start as --x0 0.3: $(first_row)"; }

# ---- an undamped wall chain started in mode 2 stays in it ----
# With unequal masses, no dampers and a wall end the chain is x'' = -M^-1 K x. exact's step
# is exp(h A) and rk4's the polynomial R(h A) of the first-order matrix A, so each maps the
# span of mode 2 (A's eigenvectors for +-i w_2) into itself: only rounding (and the CSV's
# 12 digits) reaches the other modes. Their modal coordinates q_j = phi^_j^T M x, with
# the mass-normalised shapes from --modes, stay within 1e-8 of mode 2's largest over 20 s.
chain="-n 3 --boundary wall --damping 0 --mass 1,2.5,0.7 --spring 10,14,6,9"
for integ in exact rk4; do
    # shellcheck disable=SC2086
    accepted --modes $chain || continue
    cp "$out" "$tmp/modes.csv"
    # shellcheck disable=SC2086
    accepted --headless $chain --start-mode 2 --integrator $integ --duration 20 || continue
    res=$(awk -F, '
        function abs(x) { return x < 0 ? -x : x }
        BEGIN { m[1] = 1; m[2] = 2.5; m[3] = 0.7 }
        NR == FNR { if (FNR > 1) for (i = 1; i <= 3; i++) phi[FNR - 1, i] = $(i + 2); next }
        FNR == 1 { for (j = 1; j <= 3; j++) { s = 0; for (i = 1; i <= 3; i++) s += m[i] * phi[j, i] ^ 2; norm[j] = sqrt(s) } next }
        {
            rows++
            for (j = 1; j <= 3; j++) {
                q = 0
                for (i = 1; i <= 3; i++) q += m[i] * phi[j, i] * $(i + 1)
                q = abs(q) / norm[j]
                if (q > top[j]) top[j] = q
            }
            t = $1
        }
        END { printf "%d %s %.3g %.3g %.3g\n", rows, t, top[1] / top[2], top[2], top[3] / top[2] }
    ' "$tmp/modes.csv" "$out")
    set -- $res
    if [ "$1" -eq 2001 ] && [ "$2" = 20 ] &&
        awk -v a="$3" -v b="$4" -v c="$5" 'BEGIN { exit !(a <= 1e-8 && c <= 1e-8 && b > 0.3) }'; then
        pass
    else
        fail "--start-mode 2 --integrator $integ: rows $1 to t = $2; modes 1 and 3 at $3 and $5 of mode 2 (at most 1e-8), mode 2 at $4"
    fi
done

summary
