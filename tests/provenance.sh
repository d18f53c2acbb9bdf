#!/bin/sh
# tests/provenance.sh: where a result came from. --meta puts '#' lines before the CSV
# header of --headless, --modes and --sweep (the version, the command line that repeats
# the run): the rest of the file is the plain CSV byte for byte, numpy's loadtxt with
# comments='#' reads the same table from both, and the command line, run again, makes
# the same CSV. --random without --seed says its seed (standard error in headless, the
# status line interactive), and that seed repeats the run. Prints "provenance: N passed,
# M failed".
NAME=provenance
. tests/lib/check.sh
plain_env
out=$tmp/out
err=$tmp/err

# Debian's python3, which python3-numpy and python3-pandas serve (mk/deps.sh test).
py=/usr/bin/python3
[ -x "$py" ] || py=python3

# same_table PLAIN META: pandas (comment='#') and numpy (loadtxt, comments='#'; skiprows
# counts comment lines too, so 3: the two '#' lines and the header) read from the --meta
# file the table they read from the plain one, header and every value.
same_table() {
    "$py" - "$1" "$2" <<'EOF'
import sys
import numpy as np
import pandas as pd
plain, meta = sys.argv[1], sys.argv[2]
a, b = pd.read_csv(plain), pd.read_csv(meta, comment='#')
ok = len(a) > 0 and list(a.columns) == list(b.columns) and a.equals(b)
a = np.loadtxt(plain, delimiter=',', skiprows=1, ndmin=2)
b = np.loadtxt(meta, delimiter=',', comments='#', skiprows=3, ndmin=2)
ok = ok and a.shape == b.shape and np.array_equal(a, b, equal_nan=True)
sys.exit(0 if ok else 1)
EOF
}

version=$("$SPRINGSIM" --version)
# check_meta WHAT ARGS...: the run with and without --meta, compared.
check_meta() {
    what=$1
    shift
    "$SPRINGSIM" "$@" >"$tmp/plain.csv" 2>"$err" || { fail "$what: springsim $* failed"; return; }
    head -c 1 "$tmp/plain.csv" | grep -q '#' && fail "$what: the default CSV starts with '#'" || pass
    "$SPRINGSIM" "$@" --meta >"$tmp/meta.csv" 2>"$err" || { fail "$what: --meta failed"; return; }
    [ "$(sed -n 1p "$tmp/meta.csv")" = "# $version" ] && pass ||
        fail "$what: first line '$(sed -n 1p "$tmp/meta.csv")', expected '# $version'"
    [ "$(grep -c '^#' "$tmp/meta.csv")" -eq 2 ] && [ "$(sed -n 3p "$tmp/meta.csv" | cut -c1)" != '#' ] &&
        pass || fail "$what: expected exactly two '#' lines, at the top"
    sed '1,2d' "$tmp/meta.csv" | cmp -s - "$tmp/plain.csv" && pass ||
        fail "$what: after the '#' lines, --meta's CSV is not the plain one"
    if "$py" -c 'import numpy, pandas' 2>/dev/null; then
        same_table "$tmp/plain.csv" "$tmp/meta.csv" && pass ||
            fail "$what: pandas or numpy reads another table from the --meta CSV"
    else
        fail "python3-numpy or python3-pandas is missing (mk/deps.sh test installs them)"
    fi
    # The command line, from its own words, repeats the run (the preset is not needed).
    cmd=$(sed -n '2s/^# springsim //p' "$tmp/meta.csv")
    (cd "$tmp" && eval "\"\$SPRINGSIM\" $cmd") >"$tmp/again.csv" 2>"$err"
    cmp -s "$tmp/again.csv" "$tmp/plain.csv" && pass ||
        fail "$what: 'springsim $cmd' does not repeat the run: $(head -c 200 "$err")"
}

check_meta headless --headless -p collisions --duration 3 --sample 0.05 --energy
check_meta headless-every-step --headless -n 3 --mass 1,0.3333333333333333,2 --x0 -0.5,0,0.5 \
    --wave triangle --integrator verlet --dt 0.007 --duration 0.5 --no-collisions
check_meta start-mode --headless -n 3 --mass 1,2,0.5 --start-mode 2:0.3 --duration 1 --sample 0.1
check_meta modes --modes -p 3-mass-chain --damping 0.2,0,0.1
check_meta sweep -p 3-mass-chain --sweep 0.1:2:25
check_meta sweep-springs --sweep 0.2:3:7 -n 2 --spring 10,20,30

# --meta with -o: the lines go into the file.
"$SPRINGSIM" --modes --meta -o "$tmp/modes.csv" >"$out" 2>"$err"
[ "$(sed -n 1p "$tmp/modes.csv")" = "# $version" ] && ! [ -s "$out" ] && pass ||
    fail "--modes --meta -o FILE: the file starts '$(sed -n 1p "$tmp/modes.csv")'"

# --random without --seed: the seed on standard error, and it repeats the run.
"$SPRINGSIM" --headless --random -n 4 --duration 1 --meta >"$out" 2>"$err"
seed=$(sed -n 's/^springsim: --random: seed \([0-9][0-9]*\) (--seed \1 repeats this run)$/\1/p' "$err")
if [ -z "$seed" ]; then
    fail "--headless --random: no seed said, stderr: $(head -c 200 "$err")"
else
    pass
    "$SPRINGSIM" --headless --random --seed "$seed" -n 4 --duration 1 >"$tmp/again.csv" 2>"$err"
    sed '1,2d' "$out" | cmp -s - "$tmp/again.csv" && ! [ -s "$err" ] && pass ||
        fail "--seed $seed does not repeat the --random run"
    sed -n 2p "$out" | grep -q -- "--random --seed $seed " && pass ||
        fail "--meta's command line lacks --random --seed $seed: $(sed -n 2p "$out")"
    "$SPRINGSIM" --headless --random -n 4 --duration 1 >"$tmp/other.csv" 2>/dev/null
    cmp -s "$tmp/other.csv" "$tmp/again.csv" && fail "two --random runs gave the same start" || pass
fi
# ... but a seed given is not repeated back, and --modes and --sweep do not use one.
for args in "--headless --random --seed 5 --duration 0.1" "--modes --random" "--sweep 0.1:1:3 --random"; do
    "$SPRINGSIM" $args >/dev/null 2>"$err"
    ! [ -s "$err" ] && pass || fail "springsim $args said: $(head -c 200 "$err")"
done

# Interactive: the status line says the seed.
. tests/lib/tmux.sh
start rnd 120 40 -- --random -n 3
S=rnd
wait_re 'random positions from seed [0-9]+ \(--seed repeats them\)' && pass ||
    fail "interactive --random: no seed in the status line: $(brief)"
keys R
wait_re 'random initial positions \(seed [0-9]+\)' && pass ||
    fail "interactive R: no seed in the status line: $(brief)"
keys q

summary
