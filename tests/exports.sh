#!/bin/sh
# tests/exports.sh: the exports' '#' lines make their data again (issue 22, items 11 and
# 12), through the plain mode: `export` after `run` writes the samples, whose --headless
# line run again gives the same rows; after a sweep `export` also writes its measured
# points beside the theory, whose --sweep line run again gives the same theory columns,
# and the measured points agree with the theory (a linear chain, no contacts). Run from
# the repository root as `sh tests/exports.sh`, SPRINGSIM naming the binary. Ends with
# "exports: N passed, M failed".
NAME=exports
. "$(dirname "$0")/lib/check.sh"
trap 'exit 1' HUP INT TERM
plain_env
mkdir -p "$tmp/w"

# again FILE: runs the command line on FILE's second line (the binary for "springsim"),
# its CSV into $tmp/again
again() {
    line=$(sed -n '2s/^# springsim //p' "$1")
    # shellcheck disable=SC2086
    (cd "$tmp/w" && eval "\"$SPRINGSIM\" $line" >"$tmp/again" 2>"$tmp/again.err")
}

# ---- the samples: export after 3 s; the --headless line gives the same rows ----
printf 'run 3\nexport\nquit\n' >"$tmp/in"
(cd "$tmp/w" && "$SPRINGSIM" --plain -n 3 --damping 0.3 --frequency 0.8 <"$tmp/in" >"$tmp/out" 2>&1)
f=$(ls "$tmp/w"/springsim-2*.csv 2>/dev/null | head -n 1)
if grep -q '^ok exported 301 rows (t = 0 to 3.00 s) to ./springsim-[0-9-]*\.csv$' "$tmp/out" &&
    [ -f "$f" ]; then pass; else
    fail "plain run 3, export: expected 'ok exported 301 rows (t = 0 to 3.00 s) to ./springsim-….csv'; got: $(grep export "$tmp/out")"
fi
if [ -f "$f" ] && again "$f" && [ -s "$tmp/again" ] &&
    [ "$(grep -v '^#' "$f")" = "$(cat "$tmp/again")" ]; then pass; else
    fail "the samples' --headless line ($(sed -n 2p "$f" | cut -c 1-100)…) should give the exported rows again; $(grep -v '^#' "$f" | wc -l) rows exported, $(wc -l <"$tmp/again") made, first difference: $(grep -v '^#' "$f" | diff - "$tmp/again" | sed -n 2p) $(cat "$tmp/again.err")"
fi
rm -f "$tmp/w"/*.csv

# ---- a sweep, then export: its points beside the theory ----
printf 'sweep\nrun 1000\nexport\nquit\n' >"$tmp/in"
(cd "$tmp/w" && "$SPRINGSIM" --plain -n 2 --spring 50 --damping 5 <"$tmp/in" >"$tmp/out" 2>&1)
s=$(ls "$tmp/w"/springsim-sweep-*.csv 2>/dev/null | head -n 1)
if grep -q "; exported the sweep's 40 points beside the theory to ./springsim-sweep-[0-9-]*\.csv$" "$tmp/out" &&
    [ -f "$s" ] && [ "$(ls "$tmp/w" | wc -l)" -eq 2 ]; then pass; else
    fail "plain sweep, run, export: expected the samples and the sweep's 40 points written; got: $(grep export "$tmp/out"); files: $(ls "$tmp/w" | tr '\n' ' ')"
fi
if [ -f "$s" ] && sed -n 4p "$s" | grep -qx 'frequency_hz,amp1,amp2,phase1,phase2,theory_amp1,theory_amp2,theory_phase1,theory_phase2' &&
    [ "$(grep -vc '^#' "$s")" -eq 41 ]; then pass; else
    fail "the sweep's CSV: expected 3 '#' lines, the header frequency_hz,amp1,amp2,phase1,phase2,theory_amp1,…,theory_phase2 and 40 rows; got: $(sed -n '1,6p' "$s" | cut -c 1-100 | tr '\n' '|')"
fi
# the --sweep line gives the theory columns again (frequencies to 1e-12, values to 1e-9)
if [ -f "$s" ] && again "$s" &&
    awk -F, 'NR == FNR { if ($0 !~ /^#/ && FNR > 4) { f[++n] = $1; a1[n] = $6; a2[n] = $7; p1[n] = $8; p2[n] = $9 }; next }
        /^#/ || /^frequency/ { next }
        { m++; if (m > n) bad = 1
          if (($1 - f[m]) ^ 2 > 1e-24 * f[m] ^ 2) bad = 1
          if (($2 - a1[m]) ^ 2 > 1e-18 * a1[m] ^ 2 || ($3 - a2[m]) ^ 2 > 1e-18 * a2[m] ^ 2) bad = 1
          if (($4 - p1[m]) ^ 2 > 1e-14 || ($5 - p2[m]) ^ 2 > 1e-14) bad = 1 }
        END { exit !(n == 40 && m == 40 && !bad) }' "$s" "$tmp/again"; then pass; else
    fail "the sweep's --sweep line ($(sed -n 2p "$s" | cut -c 1-80)…) should give its theory columns again: $(sed -n 5p "$s") vs $(sed -n 2p "$tmp/again") $(cat "$tmp/again.err")"
fi
# measured against the theory: within 2 % and 3 degrees at every point
if [ -f "$s" ] && awk -F, '!/^#/ && NR > 4 {
        for (i = 0; i < 2; i++) {
            m = $(2 + i); t = $(6 + i); d = $(4 + i) - $(8 + i)
            while (d > 180) d -= 360
            while (d < -180) d += 360
            if ((m - t) ^ 2 > (0.02 * t) ^ 2 || d * d > 9) bad = 1 } ; rows++ }
        END { exit !(rows == 40 && !bad) }' "$s"; then pass; else
    fail "the sweep's points should agree with the theory beside them (2 %, 3 degrees): $(sed -n '5,7p' "$s" | tr '\n' '|')"
fi
# a sweep not run: export writes the samples alone and says nothing of a sweep
rm -f "$tmp/w"/*.csv
printf 'run 1\nexport\nquit\n' >"$tmp/in"
(cd "$tmp/w" && "$SPRINGSIM" --plain <"$tmp/in" >"$tmp/out" 2>&1)
if grep -q '^ok exported 101 rows' "$tmp/out" && ! grep -q sweep "$tmp/out" &&
    [ "$(ls "$tmp/w" | wc -l)" -eq 1 ]; then pass; else
    fail "export without a sweep: expected the samples alone; got: $(grep export "$tmp/out"); files: $(ls "$tmp/w" | tr '\n' ' ')"
fi

summary
