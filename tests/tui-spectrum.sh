#!/bin/sh
# tests/tui-spectrum.sh: the spectrum view (F) in a real terminal (tmux), read off the
# screen as a person would: its title names the mass, the level axis is in dB (evenly
# spaced whole numbers, 80 dB deep, "dB" over it), the frequency axis in Hz; the labels
# f1, f2 of the natural frequencies and 1×, 3×, ... of the drive's harmonics stand where
# the frequency axis puts those frequencies (from the presets' own numbers, as
# `springsim --modes` gives them); the highest point of the curve is at the line that
# should dominate: the 3rd harmonic on mode 1 for -p square-wave, the drive for
# -p low-frequency; -p beating shows two peaks, at 0.62 and 0.712 Hz. Tab and ↓ pick the
# mass; a ghost (g) is named in the legend; F again brings the plots back; 80x24 in ASCII
# without colour keeps every label. A record too short for the axis (a few steps: its
# bins 1/(count dt) wider than the axis) says how much it needs, no curve, no peak; a mass
# that has not moved (amplitude 0) says so, no floor at -300 dB. A ghost made at t = 8 s:
# both spectra cover the time since it was made (the live one is not 60 s against the
# ghost's few seconds, which would part two equal chains).
# Run from the repository root as `sh tests/tui-spectrum.sh`, SPRINGSIM naming the binary.
# Ends with "tui-spectrum: N passed, M failed".
NAME=tui-spectrum
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"

start square 120 40 -- -p square-wave
start low 120 40 -- -p low-frequency
start beat 120 40 -- -p beating
start ascii 80 24 LANG=C LC_ALL=C NO_COLOR=1 -- -p square-wave
start early 120 40
start still 120 40 -- --amplitude 0
start young 120 40
sessions="square low beat ascii"

# Run each at 10x (space, then ] four times: 1, 2, 4, 5, 10x).
for s in $sessions; do
    if up $s; then keys Space ] ] ] ]; fi
done
sessions="$sessions early still young" # these at 1x, paused

TITLE="Spectrum of mass"

# geometry TEXT...: reads the spectrum chart and prints, one per line, "tick V COL" for
# the first and last frequency ticks, "label TEXT COL" for each TEXT (the cell its label
# marks: its middle), "peak COL" (the middle of the highest curve cells) and
# "h COL ROWS" (the curve's height in rows above the x axis, per column).
geometry() {
    plot_awk 'function ncells(t,   i, n, b) { for (i = 1; i <= length(t); i++) { b = ord[substr(t, i, 1)]; n += b < 128 || b >= 192 } return n }
    END {
        if (!plot(title)) { print "noplot"; exit }
        n = 0
        for (k = axc; k < right; k++) if (cell(axr, k) == "┬") tk[++n] = k
        # the labels under the ticks: numbers, read cell by cell
        m = 0; tok = ""
        for (k = axc; k <= right; k++) {
            ch = cell(axr + 1, k)
            if (ch ~ /^[-0-9.]$/) { if (tok == "") st = k; tok = tok ch }
            else if (tok != "") { v[++m] = tok; tok = "" }
        }
        if (n >= 2 && m == n) { print "tick", v[1], tk[1]; print "tick", v[n], tk[n] }
        split(texts, want, " ")
        for (i = 1; i in want; i++)
            for (r = top + 1; r < axtop; r++)
                if ((k = at(r, want[i])) > 0 && k > axc) { print "label", want[i], k + int((ncells(want[i]) - 1) / 2); break }
        for (r = axtop; r < axr; r++) {
            s = 0; cnt = 0
            for (k = axc + 1; k < right; k++) if (braille(c[r, k])) { s += k; cnt++ }
            if (cnt) { print "peak", s / cnt; break }
        }
        for (k = axc + 1; k < right; k++)
            for (r = axtop; r < axr; r++) if (braille(c[r, k])) { print "h", k, axr - r; break }
    }' -v "title=$TITLE" -v "texts=$*"
}
# col_of F: the column (cell) the frequency axis puts F Hz at, from the geometry in $geo
col_of() {
    awk -v f="$1" '$1 == "tick" { n++; v[n] = $2; k[n] = $3 }
        END { if (n == 2) printf "%.2f\n", k[1] + 0.25 + (f - v[1]) / (v[2] - v[1]) * (k[2] - k[1]) }' "$geo"
}
# label_col TEXT: the column of the label TEXT, from $geo
label_col() { awk -v t="$1" '$1 == "label" && $2 == t { print $3; exit }' "$geo"; }
# near A B: |A - B| <= 1.5 columns
near() { [ -n "$1" ] && [ -n "$2" ] && awk -v a="$1" -v b="$2" 'BEGIN { exit !(a - b <= 1.5 && b - a <= 1.5) }'; }
geo=$tmp/geometry

# spectrum SESSION: waits for t >= 40 s, pauses, presses F, and waits for the chart,
# drawn whole (the screen standing still), for what follows to measure
spectrum() {
    S=$1
    if ! wait_t 40 30; then
        fail "$1: the run should reach t = 40 s at 10x; screen: $(brief)"
        return 1
    fi
    keys Space F
    if settle_all 5 "has_re \"┌─+ Spectrum of mass 1's displacement: dB re 1 m, Hann window over\" &&
        has_re '┊ natural' && has Paused"; then
        pass
    else
        fail "$1: F should open a frame titled 'Spectrum of mass 1's displacement: dB re 1 m, Hann window over ...'; screen: $(brief "$scr" 'Spectrum')"
        return 1
    fi
}

# ---- -p square-wave: f1 0.5033 Hz, f2 0.8717 Hz, a square drive at 0.16776 Hz ----
if spectrum square; then
    bad=$(plot_ticks "$TITLE")
    if [ -z "$bad" ]; then pass; else fail "square: the dB axis: $bad"; fi
    # 80 dB from the top label to the bottom of the axis, "dB" above it
    span=$(plot_awk 'END { if (plot(title)) { for (r = axtop; r < axr; r++) if ((s = label(r)) != "") { if (hi == "") hi = s; lo = s } print hi - lo } }' -v "title=$TITLE")
    if [ -n "$span" ] && [ "$span" -ge 60 ] && [ "$span" -le 80 ] && has_re '^│ +dB  '; then pass; else
        fail "square: the level axis should be labelled 'dB' and span 60 to 80 dB between its labels, spans '$span'; screen: $(brief "$scr" '┤|dB')"
    fi
    if has_re '^│ Hz +0\.0 +0\.5 +1\.0 +1\.5 +2\.0 *│'; then pass; else
        fail "square: the frequency axis should read Hz 0.0 0.5 1.0 1.5 2.0 (twice f2 = 1.74 Hz, rounded out); screen: $(brief "$scr" '^│ Hz')"
    fi
    if has_re '└─━ mass 1─peak 0\.5[0-9]* Hz [0-9.-]+ dB─┃ drive 0\.168 Hz, odd harmonics─┊ natural f1\.\.f2'; then pass; else
        fail "square: the legend should read '━ mass 1 peak 0.5.. Hz .. dB ┃ drive 0.168 Hz, odd harmonics ┊ natural f1..f2'; screen: $(brief "$scr" '└─━')"
    fi
    geometry f1 f2 1× 3× 5× 7× 9× 11× 2× >"$geo"
    for lf in f1:0.5033 f2:0.8717 1×:0.16776 3×:0.50328 5×:0.8388 7×:1.17432 9×:1.50984; do
        l=${lf%%:*} f=${lf#*:}
        if near "$(label_col "$l")" "$(col_of "$f")"; then pass; else
            fail "square: the label '$l' should stand at $f Hz, column $(col_of "$f"), is at '$(label_col "$l")'; screen: $(brief "$scr" 'f1|1×')"
        fi
    done
    if [ -z "$(label_col 2×)" ]; then pass; else
        fail "square: a square wave has no even harmonics, but '2×' is marked; screen: $(brief "$scr" '1×')"
    fi
    # the highest point: the 3rd harmonic on mode 1, far above the fundamental
    if near "$(awk '$1 == "peak" { print $2 }' "$geo")" "$(col_of 0.50328)"; then pass; else
        fail "square: the curve's highest point should be at 3× = f1 (0.503 Hz, column $(col_of 0.50328)), is at column '$(awk '$1 == "peak" { print $2 }' "$geo")'; screen: $(brief "$scr" 'peak')"
    fi
    # Tab, ↓ ↓: mass 2, named in the title and the legend
    keys Tab Down Down
    if settle_all 3 "has_re \"┌─+ Spectrum of mass 2's displacement\" && has '━ mass 2'"; then pass; else
        fail "square: Tab ↓ ↓ should select mass 2 and the spectrum follow it; screen: $(brief "$scr" 'Spectrum|━ mass')"
    fi
    keys Tab
    if settle_all 3 "has_re \"┌─+ Spectrum of mass 2's\" && has Controls"; then pass; else
        fail "square: back to the controls (Tab), the spectrum should stay on mass 2; screen: $(brief "$scr" 'Spectrum')"
    fi
    # a ghost: named in the legend while there is one (running again, for its samples)
    keys Space g
    if wait_re '└─━ mass 2─peak [^─]*─┄ghost─┃ drive' 3; then pass; else
        fail "square: with a ghost (g) the legend should name it after the peak, '┄ghost'; screen: $(brief "$scr" '└─━')"
    fi
    keys g
    if wait_all 3 "has_re '└─━ mass 2─peak [^─]*─┃ drive' && lacks '┄ghost'"; then pass; else
        fail "square: g again should drop the ghost and its legend; screen: $(brief "$scr" '└─━')"
    fi
    keys F
    if wait_all 3 "has '1 Displacement (m)' && lacks \"\$TITLE\""; then pass; else
        fail "square: F again should bring back the plots; screen: $(brief)"
    fi
fi

# ---- -p low-frequency: sine drive at 0.1 Hz, well below f1 0.503 Hz, damping 0.5 ----
if spectrum low; then
    geometry f1 f2 1× 3× >"$geo"
    for lf in f1:0.5033 f2:0.8717 1×:0.1; do
        l=${lf%%:*} f=${lf#*:}
        if near "$(label_col "$l")" "$(col_of "$f")"; then pass; else
            fail "low: the label '$l' should stand at $f Hz, column $(col_of "$f"), is at '$(label_col "$l")'; screen: $(brief "$scr" 'f1|1×')"
        fi
    done
    if [ -z "$(label_col 3×)" ] && has '┃ drive 0.100 Hz─'; then pass; else
        fail "low: a sine drive has its fundamental only: no '3×', the legend 'drive 0.100 Hz' alone; screen: $(brief "$scr" '1×|drive')"
    fi
    # the transients have died away: the drive's line is the highest
    if near "$(awk '$1 == "peak" { print $2 }' "$geo")" "$(label_col 1×)"; then pass; else
        fail "low: the curve's highest point should be under '1×' (the drive, column $(label_col 1×)), is at column '$(awk '$1 == "peak" { print $2 }' "$geo")'; screen: $(brief "$scr" 'peak')"
    fi
fi

# ---- -p beating: two lines 0.092 Hz apart, parted once the record is long enough ----
S=beat
if wait_t 70 30; then
    if spectrum beat; then
        if has_re "┌─+ Spectrum of mass 1's displacement: dB re 1 m, Hann window over the last 60 s"; then pass; else
            fail "beat: after 70 s the title should say 'over the last 60 s'; screen: $(brief "$scr" 'Spectrum')"
        fi
        geometry f1 1× >"$geo"
        a=$(col_of 0.62) b=$(col_of 0.711763)
        # two maxima, one at each line, and between them a dip of 3 rows or more
        twin=$(awk -v a="$a" -v b="$b" '$1 == "h" { h[$2 + 0] = $3 + 0 }
            END {
                for (k = int(a - 1.5); k <= a + 1.5; k++) if (k >= a - 1.5 && h[k] > ha) { ha = h[k]; ka = k }
                for (k = int(b - 1.5); k <= b + 1.5; k++) if (k >= b - 1.5 && h[k] > hb) { hb = h[k]; kb = k }
                lo = 1e9
                for (k = ka + 1; k < kb; k++) if (k in h && h[k] < lo) lo = h[k]
                print (kb > ka + 1 && ha - lo >= 3 && hb - lo >= 3) ? "yes" : "no " ha " " hb " " lo
            }' "$geo")
        if [ "$twin" = yes ]; then pass; else
            fail "beat: expected two peaks at 0.62 Hz (column $a) and 0.712 Hz (column $b) with a dip between (heights, dip: ${twin#no }); screen: $(brief "$scr" 'peak')"
        fi
        if near "$(label_col f1)" "$b" && near "$(label_col 1×)" "$a"; then pass; else
            fail "beat: f1 should mark 0.712 Hz (column $b) and 1× 0.62 Hz (column $a), are at '$(label_col f1)', '$(label_col 1×)'; screen: $(brief "$scr" 'f1|1×')"
        fi
    fi
else
    fail "beat: the run should reach t = 70 s at 10x; screen: $(brief)"
fi

# ---- 80x24, LANG=C, NO_COLOR: ASCII, every label whole ----
S=ascii
if wait_t 40 30; then
    keys Space F
    if settle_all 5 "has_re '^\+-+ Spectrum of mass 1 \(dB\), the last 60 s -+\+' && has Paused"; then pass; else
        fail "ascii 80x24: F should show the short title 'Spectrum of mass 1 (dB), the last 60 s'; screen: $(brief "$scr" 'Spectrum')"
    fi
    if has_re '^\| +f1 +f2 +\|' && has_re '^\| +dB +1x +3x +5x +7x +9x +11x +\|' &&
        has_re '^\| Hz +0\.0 +0\.5 +1\.0 +1\.5 +2\.0\|'; then pass; else
        fail "ascii 80x24: expected the rows 'f1 f2', 'dB 1x 3x 5x 7x 9x 11x' and 'Hz 0.0 0.5 1.0 1.5 2.0'; screen: $(brief "$scr" 'f1|dB|Hz')"
    fi
    cap_raw
    if ! LC_ALL=C grep -q "$(printf '[\200-\377]')" "$scr"; then pass; else
        fail "ascii 80x24: a byte >= 0x80 reached the terminal; screen: $(brief)"
    fi
else
    fail "ascii: the run should reach t = 40 s at 10x; screen: $(brief)"
fi

# ---- too few samples, no motion: said in words, no curve or peak drawn ----
S=early
if up early; then
    # 0.06 s: the unpadded bins 16.7 Hz apart against an axis to 2 Hz (twice f2)
    keys F . . . . . .
    if wait_t 0.06 3 && settle_all 3 "has_re '│ needs [0-9.]+ s of samples: 0\.[0-9] s so far' &&
        lacks peak && lacks -300"; then pass; else
        fail "early: 6 steps should say 'needs .. s of samples: .. s so far', no peak, no -300 dB floor; screen: $(brief "$scr" 'Spectrum|needs|peak')"
    fi
    # once the record holds 8 bins of the axis (4 s for an axis to 2 Hz) the spectrum is drawn
    keys Space
    if wait_t 4.2 10 && wait_all 3 "has_re '└─━ mass 1─peak 0\.[0-9]+ Hz' && lacks needs"; then pass; else
        fail "early: after 4 s the spectrum and its peak should be drawn; screen: $(brief "$scr" 'Spectrum|needs|peak')"
    fi
fi
S=still
if up still; then
    keys F Space
    if wait_t 5 10 && wait_all 3 "has 'mass 1 has not moved: no spectrum to show' && lacks peak &&
        lacks -300"; then pass; else
        fail "still: with amplitude 0 the view should say 'mass 1 has not moved', no peak, no -300 dB; screen: $(brief "$scr" 'Spectrum|moved|peak')"
    fi
fi
S=young
if up young; then
    keys Space
    if wait_t 8 15; then
        keys g F
        if wait_for 'since the ghost was made' 3; then pass; else
            fail "young: right after g the spectrum should wait for samples 'since the ghost was made'; screen: $(brief "$scr" 'Spectrum|needs')"
        fi
        # at t >= 14 s: a span of about t - 8 s, not the live chain's 14 s
        if wait_t 14 15 && wait_all 3 "has '┄ghost' && has 'Hann window over'"; then
            t=$(sed -n '1s/.*t = \([0-9.]*\) s.*/\1/p' "$scr")
            span=$(sed -n "s/.*Hann window over \([0-9]*\) s so far.*/\1/p" "$scr")
            if [ -n "$span" ] && awk -v t="$t" -v s="$span" 'BEGIN { exit !(s >= t - 9.5 && s <= t - 6.5) }'; then pass; else
                fail "young: at t = $t s with a ghost made at 8 s the spectrum should cover about $t - 8 s, covers '$span' s; screen: $(brief "$scr" 'Spectrum')"
            fi
        else
            fail "young: the spectrum with its ghost should be drawn by t = 14 s; screen: $(brief "$scr" 'Spectrum|needs')"
        fi
    fi
fi

all_alive $sessions
summary
