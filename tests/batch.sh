#!/bin/sh
# tests/batch.sh: --batch end to end (issue 32): each row's output byte for byte the
# --summary row the same run gives alone (lists, choices, a start, different N, options
# on the command line), bad rows said in one line naming the line while the others still
# run (exit 1), bad headers refused before any run (exit 2), -o, and the order under GNU
# parallel --pipe --keep-order; then the README's study, taken from the file.
# Prints one line per failing case, then "batch: N passed, M failed".

NAME=batch
. "$(dirname "$0")/lib/check.sh"
trap 'exit 1' HUP INT TERM
plain_env
root=$(cd "$(dirname "$0")/.." && pwd)

# alone FILE ARGS...: what the runs of FILE's rows write one by one with --summary, each
# row's fields given as options (a quoted field, a list, without its quotes), the header
# kept where N changes from the row before: what --batch FILE ARGS must write.
alone() {
    file=$1
    shift
    last=
    tail -n +2 "$file" | while IFS= read -r line; do
        # The fields as options, by the header's names (quoted lists hold no quote).
        args=$(printf '%s\n' "$line" | awk -v names="$(head -n 1 "$file")" '
            BEGIN { n = split(names, name, ",") }
            { s = $0; i = 0
              while (length(s) > 0 || i < n) {
                  i++
                  if (substr(s, 1, 1) == "\"") { s = substr(s, 2); j = index(s, "\""); f = substr(s, 1, j - 1); s = substr(s, j + 2) }
                  else { j = index(s, ","); if (j == 0) { f = s; s = "" } else { f = substr(s, 1, j - 1); s = substr(s, j + 1) } }
                  if (f == "true") printf " --%s", name[i]
                  else if (f != "" && f != "false") printf " --%s=%s", name[i], f
                  if (i >= n) break
              } }')
        # shellcheck disable=SC2086
        "$SPRINGSIM" --summary "$@" $args >"$tmp/one" 2>/dev/null || continue
        head -n 1 "$tmp/one" >"$tmp/h"
        n=$(cut -d, -f1 "$tmp/one" | sed -n 2p)
        [ "$n" = "$last" ] || cat "$tmp/h"
        sed -n 2p "$tmp/one"
        last=$n
    done
}

# Rows of every kind: N from 1 to 6 and back, lists in quotes, choices, a start, an
# empty field (the command line's value), a flag, other dt and integrators.
cat >"$tmp/runs.csv" <<'EOF'
masses,mass,damping,frequency,wave,integrator,dt,x0,no-collisions,duration
3,,0.1,0.5,sine,rk4,0.01,,,8
3,"1,2,1.5",0.3,0.7,square,verlet,0.005,,,8
1,2,0,1,triangle,euler,0.001,0.3,true,5
6,,"0.1,0.2,0.3,0.4,0.5,0.6",1.2,sawtooth,semi-implicit,0.01,,false,8
6,1.5,,0.9,,,,"0.1,0,0,0,0,-0.1",,8
3,,1,2,sine,exact,0.01,,,8
EOF
run --batch "$tmp/runs.csv" --amplitude 0.4
alone "$tmp/runs.csv" --amplitude 0.4 >"$tmp/want"
# (euler undamped and semi-implicit at 0.01 s are warned about, as they are alone.)
if [ "$rc" -eq 0 ] && ! grep -v ': warning: ' "$err" >/dev/null &&
    [ "$(grep -vc '^masses,' "$tmp/want")" = 6 ] &&
    cmp -s "$out" "$tmp/want"; then
    pass
else
    fail "$cmd: exit $rc, not the six runs' own rows: $(diff "$out" "$tmp/want" | head -c 300)"
fi
# Four headers: N goes 3, 3, 1, 6, 6, 3.
[ "$(grep -c '^masses,' "$out")" = 4 ] && pass ||
    fail "$cmd: $(grep -c '^masses,' "$out") headers (expected 4: N 3, 1, 6, 3)"

# A summary's own header and rows read back as a study: the settings columns repeat it.
run --batch - <<'EOF'
masses,mass,spring,damping,frequency,amplitude,wave,dt,integrator
2,1,10,0.1,1,0.1,sine,0.01,rk4
EOF
"$SPRINGSIM" --summary --duration 10 >"$tmp/default"
cmp -s "$out" "$tmp/default" && [ "$rc" -eq 0 ] && pass ||
    fail "$cmd: the default run as a row differs from --summary alone"

# Bad rows: each one line naming FILE:LINE (and what is wrong), the others' rows as
# alone, exit 1. Line 3 is not a number, 4 a field short, 5 an unclosed quote, 6 blows up
# (euler past its stability limit), 8 a list of the wrong length; 7 and 9 are good.
cat >"$tmp/bad.csv" <<'EOF'
masses,damping,integrator,dt,spring,duration
2,0.1,rk4,0.01,10,5
2,abc,rk4,0.01,10,5
2,0.1,rk4,0.01,10
2,"0.1,rk4,0.01,10,5
2,0,euler,0.05,1000,100
2,0.2,,,,5
2,"1,2,3",,,,5
3,0.2,,,,5
EOF
run --batch "$tmp/bad.csv" --no-collisions
printf '%s\n' 'masses,damping,integrator,dt,spring,duration' '2,0.1,rk4,0.01,10,5' \
    '2,0.2,,,,5' '3,0.2,,,,5' >"$tmp/good.csv"
alone "$tmp/good.csv" --no-collisions >"$tmp/want"
cmp -s "$out" "$tmp/want" && pass || fail "$cmd: the good rows' output differs from theirs alone"
[ "$rc" -eq 1 ] && pass || fail "$cmd: exit $rc (expected 1)"
for want in "bad.csv:3: damping: 'abc' is not a number" "bad.csv:4: has 5 fields" \
    "bad.csv:5: has a quote that is not closed" "bad.csv:6: the simulation blew up" \
    "bad.csv:8: damping: '1,2,3' has 3 values for 2 masses"; do
    grep -qF "$want" "$err" && pass || fail "$cmd: no line '$want': $(show "$err")"
done
# One line a bad row, besides the warning that dt is past euler's stability limit.
[ "$(grep -vc ': warning: ' "$err")" = 5 ] && pass ||
    fail "$cmd: $(grep -vc ': warning: ' "$err") lines on stderr (expected 5, one a bad row)"
! LC_ALL=C grep -q '[[:cntrl:]]' "$err" && pass || fail "$cmd: control bytes on stderr"

# -o with a bad row: the file holds the good rows (in place, no temporary left), exit 1.
run --batch "$tmp/bad.csv" --no-collisions -o "$tmp/study.csv"
if [ "$rc" -eq 1 ] && ! [ -s "$out" ] && cmp -s "$tmp/study.csv" "$tmp/want" &&
    [ "$(ls "$tmp" | grep -c tmp)" = 0 ]; then
    pass
else
    fail "$cmd: exit $rc, or the file is not the good rows"
fi

# A value with control bytes is escaped in its line.
printf 'damping\n\033[31m\n' >"$tmp/esc.csv"
run --batch "$tmp/esc.csv"
[ "$rc" -eq 1 ] && grep -qF '\x1b[31m' "$err" && ! LC_ALL=C grep -q "$(printf '\033')" "$err" &&
    pass || fail "$cmd: exit $rc, the escape not escaped: $(show "$err")"

# Refused before any run (exit 2, one line, no output): headers naming what a row cannot
# give, twice the same, nothing at all; options a summary has no use for.
printf 'masses,sample\n2,0.1\n' >"$tmp/h1.csv"
refused "'sample', is not a setting a run can give" --batch "$tmp/h1.csv"
printf 'damping,frequency,damping\n0.1,1,0.2\n' >"$tmp/h2.csv"
refused "column 3, 'damping', names the same setting as column 1" --batch "$tmp/h2.csv"
printf 'masses,\033]0;x\007\n' >"$tmp/h3.csv"
refused "is not a setting a run can give" --batch "$tmp/h3.csv"
: >"$tmp/empty.csv"
refused "empty (expected a header naming settings" --batch "$tmp/empty.csv"
refused "--meta: a --batch study's rows share one header" --batch "$tmp/runs.csv" --meta
refused "--energy: applies to --headless's rows" --batch "$tmp/runs.csv" --energy
refused "--figure: a --summary run has one row" --batch "$tmp/runs.csv" --figure "$tmp/f.png"
refused "give only one of --headless, --modes, --sweep, --sweep-run, --batch" --batch "$tmp/runs.csv" --modes
# A file that cannot be read: exit 1, its reason.
run --batch "$tmp/none.csv"
[ "$rc" -eq 1 ] && grep -qF 'none.csv: No such file or directory' "$err" && pass ||
    fail "$cmd: exit $rc: $(show "$err")"

# GNU parallel: blocks of 3 rows over 4 jobs, in order, the same table as one process.
awk 'BEGIN { print "damping,frequency"
             for (i = 0; i < 20; i++) printf "%.2f,%.2f\n", 0.05 + 0.05 * (i % 5), 0.4 + 0.03 * i }' \
    >"$tmp/grid.csv"
"$SPRINGSIM" --batch "$tmp/grid.csv" --duration 20 >"$tmp/one-process"
if command -v parallel >/dev/null 2>&1; then
    parallel --will-cite --pipe --keep-order --header : -N 3 -j 4 "$SPRINGSIM" --batch - \
        --duration 20 <"$tmp/grid.csv" >"$tmp/blocks" 2>"$err"
    awk 'NR == 1 || !/^masses,/' "$tmp/blocks" >"$tmp/joined"
    [ "$(grep -c '^masses,' "$tmp/blocks")" = 7 ] && pass ||
        fail "parallel --pipe: $(grep -c '^masses,' "$tmp/blocks") headers (expected 7 blocks)"
    cmp -s "$tmp/joined" "$tmp/one-process" && [ "$(awk 'END { print NR }' "$tmp/joined")" = 21 ] &&
        pass || fail "parallel --pipe --keep-order: not the one process's table in order"
else
    fail "GNU parallel is not installed (mk/deps.sh test installs it)"
fi

# The README's study, exactly as written there: the block from "printf 'damping" to the
# --batch line, then the parallel block, run by sh with springsim on the PATH; the two
# tables the same, each row the run's own --summary row.
study=$(awk '/^    printf .damping,frequency/ { on = 1 } on { sub(/^    /, ""); print }
             on && /--batch/ { exit }' "$root/README.md")
spread=$(awk '/^    parallel --pipe / { on = 1 } on { sub(/^    /, ""); print } on && !/\\$/ { exit }' \
    "$root/README.md")
if [ -z "$study" ] || [ -z "$spread" ]; then
    fail "README.md has no study (printf 'damping... --batch) or no 'parallel --pipe' block"
else
    mkdir -p "$tmp/bin" "$tmp/study"
    ln -s "$SPRINGSIM" "$tmp/bin/springsim"
    (cd "$tmp/study" && PATH=$tmp/bin:$PATH HOME=$tmp sh -c "$study" && mv study.csv one.csv &&
        PATH=$tmp/bin:$PATH HOME=$tmp sh -c "$spread") >"$out" 2>"$err"
    rc=$?
    if [ "$rc" -ne 0 ] || ! [ -s "$tmp/study/study.csv" ]; then
        fail "the README's study: exit $rc, no table; stderr: $(show "$err")"
    else
        cmp -s "$tmp/study/one.csv" "$tmp/study/study.csv" && pass ||
            fail "the README's study: parallel's table differs from one process's"
        rows=$(grep -vc '^masses,' "$tmp/study/study.csv")
        [ "$rows" = 9 ] && [ "$(grep -c '^masses,' "$tmp/study/study.csv")" = 1 ] && pass ||
            fail "the README's study: $rows rows (expected 9 under one header)"
        one=$(printf '%s\n' "$study" | sed -n 's/ --batch runs.csv.*//p')
        alone "$tmp/study/runs.csv" $(printf '%s\n' "$one" | sed 's/^springsim //') \
            >"$tmp/want"
        cmp -s "$tmp/want" "$tmp/study/one.csv" && pass ||
            fail "the README's study: rows differ from the runs alone"
    fi
fi

# A row's setting refused beside the others is named as its column, as a refused field is
# (no '--': the row gave it); one the command line gave keeps its '--'.
printf '%s\n' 'masses,force-on,force,spring-damping,wave' '2,3,1,,' '2,1,1,"0,0,1",square' \
    >"$tmp/cross.csv"
run --batch "$tmp/cross.csv" --no-collisions
for want in "cross.csv:2: force-on: '3' is out of range for 2 masses" \
    "cross.csv:3: spring-damping: '1' on the motor's spring"; do
    grep -qF "$want" "$err" && pass || fail "$cmd: no line '$want': $(show "$err")"
done
! grep -q -- ': --' "$err" && pass || fail "$cmd: a row's setting named as an option: $(show "$err")"
printf 'masses\n2\n' >"$tmp/cmdline.csv"
run --batch "$tmp/cmdline.csv" --no-collisions --force-on 3 --force 1
grep -qF "cmdline.csv:2: --force-on: '3' is out of range" "$err" && pass ||
    fail "$cmd: the command line's --force-on not named as given: $(show "$err")"

summary
