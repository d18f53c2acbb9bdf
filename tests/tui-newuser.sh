#!/bin/sh
# tests/tui-newuser.sh: what a new user met (issue 22), as a person sees it in tmux: at
# 60x20 the controls scroll to the selection and the frame says how many are out of
# sight (at 80x24 the list scrolls by three and the frequency bar and the natural frequencies
# stay); the Graphics control shows braille in tmux and says why sixel and kitty cannot be
# (issue 18); with ten masses at 80x24 the legends and the natural frequencies end in "…"
# and keep the motor; the energy view's drift is never cut; while dt is past a limit the
# status line says so after the warning has gone. Run from the repository root as
# `sh tests/tui-newuser.sh`, SPRINGSIM naming the binary. Ends with "tui-newuser: N
# passed, M failed".
NAME=tui-newuser
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"

start small 60 20 -- -p 3-mass-chain
start gfx 80 24 -- -p 3-mass-chain
start ten 80 24 -- -n 10 --random --seed 5
start energy 60 20 -- -p 3-mass-chain
start euler 80 24 -- --integrator euler --dt 0.05
start fine 80 24 -- -p 3-mass-chain
start c8 100 30 TERM=xterm -- -n 6 --start-mode 2 --amplitude 0
start c8e 100 30 TERM=xterm -- -p square-wave
start c256 100 30 -- -n 6 --start-mode 2 --amplitude 0
start mono 100 30 NO_COLOR=1 -- -p 3-mass-chain
start help80 80 24
start help60 60 20
start menu120 120 40
start vt100 80 24 TERM=vt100
start hide 100 30 NO_COLOR=1 -- -p 3-mass-chain
start top 100 30 -- -p 3-mass-chain

# row N of the screen, and the controls' frame (the right-hand column from its corner)
row() { sed -n "${1}p" "$scr"; }
controls() { LC_ALL=$U8 sed -n '/┌ Controls/,/^.*┘$/p' "$scr" | LC_ALL=$U8 sed 's/.*\(┌ Controls\)/\1/; s/.*││//; s/.*┘└/└/'; }

# ---- 60x20: 16 controls in 11 rows ----
if up small; then
    if has_re '└─+ ↓ 5 more ─┘' && lacks '↑ 5 more' && has 'Frequency' && lacks 'Refresh'; then
        pass
    else
        fail "60x20: the controls' frame should say '↓ 5 more' below Frequency; screen: $(brief "$scr" 'more|Frequency')"
    fi
    keys Up # wraps to the last control, Graphics
    if wait_re '▸Graphics +auto \(braille\)' 3 && has_re 'Controls ─+ ↑ 5 more ─┐' &&
        has_re 'Refresh +normal' && has 'Speed' && lacks '↓ 5 more' && lacks 'Preset '; then
        pass
    else
        fail "60x20: ↑ from Preset should scroll to ▸Graphics 'auto (braille)' (tmux), Refresh and Speed above it, the frame saying '↑ 5 more'; screen: $(brief "$scr" 'more|Graphics|Refresh|Speed')"
    fi
    keys Up # Refresh: the list stays where it is
    if wait_re '▸Refresh +normal' 3 && has_re 'Controls ─+ ↑ 5 more ─┐' && has 'Graphics'; then pass; else
        fail "60x20: ↑ from Graphics should select ▸Refresh, the list still scrolled ('↑ 5 more'); screen: $(brief "$scr" 'more|Graphics|Refresh')"
    fi
    keys Down Down # wraps to Preset: the list scrolls back
    if settle_all 3 "has_re '▸Preset' && has '↓ 5 more' && lacks '↑ 5 more'"; then pass; else
        fail "60x20: ↓ from Graphics should scroll back to ▸Preset; screen: $(brief "$scr" 'more|Preset')"
    fi
fi

# ---- 80x24: 13 of 16 controls, the bar and the natural frequencies; Graphics ----
# the bottom line of the controls' frame, and the row of its natural frequencies
bottom_more() { has_re '└─+ ↓ 3 more ─┘$' && has_re '│ [0-9.]+ [0-9.]+ [0-9.]+ Hz +│$' && has '5Hz'; }
if up gfx; then
    if bottom_more && has_re 'Force on +mass 1' && lacks 'Speed'; then pass; else
        fail "80x24: the controls should end at Force on with '↓ 3 more', the frequency bar and the natural frequencies kept; screen: $(brief "$scr" 'more|Force|Hz')"
    fi
    keys Up # wraps to Graphics: three rows up, the bar and the frequencies stay
    if wait_re '▸Graphics +auto \(braille\)' 3 && has_re 'Controls ─+ ↑ 3 more ─┐' &&
        lacks 'Preset ' && has_re '│ [0-9.]+ [0-9.]+ [0-9.]+ Hz +│$'; then pass; else
        fail "80x24: ↑ from Preset should show ▸Graphics 'auto (braille)' (tmux), '↑ 3 more', the natural frequencies kept; screen: $(brief "$scr" 'more|Graphics|Hz')"
    fi
    # sixel and kitty cannot be inside tmux: the control and the status line say so
    keys Right
    if wait_re '▸Graphics +sixel: braille' 3 && has 'Graphics sixel: braille inside tmux or screen'; then
        pass
    else
        fail "80x24 in tmux: Graphics → sixel should show 'sixel: braille' and say why; screen: $(brief "$scr" 'Graphics')"
    fi
    keys Right
    if wait_re '▸Graphics +kitty: braille' 3 && has 'Graphics kitty: braille inside tmux or screen'; then
        pass
    else
        fail "80x24 in tmux: Graphics → kitty should show 'kitty: braille' and say why; screen: $(brief "$scr" 'Graphics')"
    fi
    keys Right
    if wait_re '▸Graphics +braille +│' 3 && lacks 'inside tmux'; then pass; else
        fail "80x24: Graphics → braille should show 'braille' and no reason; screen: $(brief "$scr" 'Graphics|tmux')"
    fi
    # typed: a bad value names itself and what is allowed; a good one is set
    keys Enter
    wait_for 'Graphics =' 3
    text sepia
    keys Enter
    if wait_for "graphics: 'sepia'" 3 && has 'braille' && has_re '▸Graphics +braille +│'; then pass; else
        fail "80x24: typing sepia into Graphics should be refused with what it allows, the control kept; screen: $(brief "$scr" 'sepia|Graphics')"
    fi
    keys Enter
    wait_for 'Graphics =' 3
    text auto
    keys Enter
    if wait_re '▸Graphics +auto \(braille\)' 3; then pass; else
        fail "80x24: typing auto into Graphics should set it back ('auto (braille)'); screen: $(brief "$scr" 'Graphics')"
    fi
    # the braille plots went on all along (a plot's row: "│" and blanks, then braille; the
    # chain's rows start "│▓▓")
    keys Space
    if wait_t 1 10 && LC_ALL=C grep -q "$(printf '^\342\224\202  .*\342[\240-\243]')" "$scr"; then pass; else
        fail "80x24: the plots should be braille after the Graphics control went round; screen: $(brief)"
    fi
fi

# ---- 80x24, ten masses: nothing dropped unsaid ----
if up ten; then
    # plot 1's legend: the masses that fit, "…", and the motor
    if has_re '└─━1━2━3━4━5━6━7…─┅motor─+┘'; then pass; else
        fail "ten masses at 80x24: plot 1's legend should read '━1━2…━7…┅motor'; screen: $(brief "$scr" '━1')"
    fi
    # plot 4's legend has room for all ten side by side
    if has_re '┘└─━1━2━3━4━5━6━7━8━9━10─+┘'; then pass; else
        fail "ten masses at 80x24: plot 4's legend should name all ten; screen: $(brief "$scr" '━1')"
    fi
    # the natural frequencies: as many as fit, then "…" (not 4 of 10 unsaid)
    if has_re '│ 0\.143 0\.284 0\.418 … +│$'; then pass; else
        fail "ten masses at 80x24: the natural frequencies should end in '…'; screen: $(brief "$scr" '0\.143')"
    fi
    # the Frequency control's mode mark keeps off the border
    if has_re 'Frequency  1\.000 Hz ◆f10 │'; then pass; else
        fail "ten masses at 80x24: 'Frequency 1.000 Hz ◆f10' should leave a column before the border; screen: $(brief "$scr" 'Frequency')"
    fi
fi

# ---- 60x20, the energy view: every energy named or "…", the drift whole ----
if up energy; then
    keys Space
    wait_t 2 10
    keys e
    if wait_all 3 "has_re '│ drift [0-9.]+e[-+][0-9]+ of the peak +│' && has_re '━kin [0-9.e+-]+ ━pot' &&
        has_re '━damp [0-9.e+-]+ ━motor [0-9.e+-]+ +… │'"; then
        pass
    else
        fail "60x20 energy view: brief names ('━kin', '━pot', '━damp', '━motor', then '…') and the whole 'drift … of the peak' line; screen: $(brief "$scr" 'drift|━')"
    fi
fi

# ---- dt past a limit: the status line says so while it is ----
if up euler; then
    wait_re 'unstable' 3
    keys Space
    # once it has run (t past 0): the status line, and the message gone from the last row
    wait_re '(Running|Paused) t = (0\.0*[1-9]|[1-9])' 5
    if wait_all 3 "row 1 | grep -qE '(Running|Paused) t = [0-9.]+ s │ dt unstable │' && ! row 24 | grep -q 'unstable with'"; then
        pass
    else
        fail "euler at dt 0.05: after space the status line should still say 'dt unstable'; screen: $(brief "$scr")"
    fi
fi
if up fine; then
    if row 1 | grep -qE 'dt (unstable|inaccurate|coarse)'; then
        fail "rk4 at dt 0.01: the status line says dt is past a limit; screen: $(brief "$scr")"
    else
        pass
    fi
fi

# ---- colours: every trace told apart, in 8 colours as in 256, and without ----
# attr TEXT: the colour (fg=, bold=, rev=) in force where TEXT first starts on the screen
# as sent (capture-pane -e), from the escapes before it on its line
attr() {
    tm capture-pane -e -p -t "$S" | awk -v t="$1" '
        BEGIN { esc = sprintf("%c", 27) }
        index($0, t) {
            fg = "d"; bold = 0; rev = 0; s = $0
            while (length(s) > 0) {
                if (substr(s, 1, length(t)) == t) { printf "fg=%s bold=%d rev=%d\n", fg, bold, rev; exit }
                if (substr(s, 1, 2) == esc "[") {
                    e = index(s, "m"); n = split(substr(s, 3, e - 3), a, ";"); s = substr(s, e + 1)
                    if (n == 0) { fg = "d"; bold = 0; rev = 0 }
                    for (k = 1; k <= n; k++) {
                        v = a[k] + 0
                        if (v == 0) { fg = "d"; bold = 0; rev = 0 }
                        else if (v == 1) bold = 1
                        else if (v == 22) bold = 0
                        else if (v == 7) rev = 1
                        else if (v == 27) rev = 0
                        else if (v >= 30 && v <= 37) fg = v - 30
                        else if (v >= 90 && v <= 97) fg = v - 82
                        else if (v == 39) fg = "d"
                        else if (v == 38 && a[k + 1] == 5) { fg = a[k + 2]; k += 2 }
                    }
                    continue
                }
                s = substr(s, 2)
            }
        }'
}
# ends: the mass digits drawn in reverse video where the curves end (the time axis is
# absolute, so at t = 3 s the curves end a third of the way in), from the plot's title
# row down, as the screen was sent
ends() {
    e=$(printf '\033')
    tm capture-pane -e -p -t "$S" | LC_ALL=$U8 awk '/Displacement/ { p = 1 } p' |
        LC_ALL=$U8 grep -oE "$e\[([0-9]+;)*7m($e\[[0-9;]*m)*[0-9]" |
        LC_ALL=$U8 sed "s/$e\[[0-9;]*m//g" | sort -u | tr -d '\n'
}
for s in c8 c256; do
    if up $s; then
        motor=$(attr '┅motor')
        same= yellow=
        for i in 1 2 3 4 5 6; do
            a=$(attr "━$i")
            [ "$a" = "$motor" ] && same="$same $i"
            case $a in fg=3\ * | fg=11\ *) yellow="$yellow $i" ;; esac
        done
        if [ -n "$motor" ] && [ -z "$same" ] && [ -z "$yellow" ]; then pass; else
            fail "$s: the motor ($motor) should be no mass's colour (same:$same) and no mass yellow (yellow:$yellow)"
        fi
        keys Space
        wait_t 3 10
        keys Space 1
        settle_all 5 "has_re '(▸|>) Paused' && has '0 all plots'"
        # 8 colours tell five masses apart: the six curves end in their digits; 256 tell ten
        if [ $s = c8 ]; then want=123456; else want=; fi
        if [ "$(ends)" = "$want" ]; then pass; else
            fail "$s: the curves' end digits should be '$want', are '$(ends)'; screen: $(brief "$scr" '││')"
        fi
    fi
done
if up c8e; then
    keys e
    wait_for 'contact' 3
    d=$(attr '━ damped') c=$(attr '━ contact') m=$(attr '━ motor')
    if [ -n "$d" ] && [ "$d" != "$c" ] && [ "$m" != "$c" ] && [ "$m" != "$d" ]; then pass; else
        fail "8 colours, energy view: damped ($d), contact ($c) and motor ($m) should differ"
    fi
fi
if up mono; then
    keys Space
    wait_t 3 10
    keys Space 1
    settle_all 5 "has_re '(▸|>) Paused' && has '0 all plots'"
    # without colour each curve ends in its digit, in reverse video
    if [ "$(ends)" = 123 ]; then pass; else
        fail "NO_COLOR: the three curves should end in 1, 2, 3 in reverse video; ends '$(ends)'; screen: $(brief "$scr" '││')"
    fi
fi

# ---- boxes over the screen: a blank cell around them, nothing beneath at their edges ----
for s in help80 help60; do
    if up $s; then
        keys '?'
        if settle_all 3 "has_re '^ ┌─+ Keys ─+┐ ?\$' && has_re '^ │ space +start / pause +│ ?\$' &&
            ! has_re '^(┌┌|││|└│|┌│|└└)' && ! has_re '(┐┐|││|│┘|│┐|┘┘)\$'"; then pass; else
            fail "$s: the help box should stand a blank column inside the screen's edges, no frame beneath doubling its border; screen: $(brief "$scr" '┌┌|││|Keys')"
        fi
    fi
done
S=help80
if alive help80; then
    keys Escape p
    # the highlighted row beneath (the Preset control) shows nowhere at the menu's edge
    if settle_all 3 "has_re '^ ┌─+ Presets ─+┐ ?\$' && has_re '^ │ beating  ' && ! has_re '─┐ ?▸|│ ?▸|┐▸'"; then pass; else
        fail "80x24: the preset menu should stand clear of the controls' highlighted row; screen: $(brief "$scr" 'Presets|beating|▸')"
    fi
fi
if up menu120; then
    keys p
    # as wide as the descriptions need where there is room: a short one whole
    if wait_for ' Presets ' 3 &&
        has_re '│ high-frequency  Two masses driven at 3 Hz, far above their modes: the response is attenuated +│'; then
        pass
    else
        fail "120x40: the preset menu should show 'high-frequency' whole; screen: $(brief "$scr" 'high-frequency')"
    fi
fi
# ---- TERM=vt100 cannot hide its cursor: it waits on the status line's first cell ----
if up vt100; then
    if [ "$(tm display -p -t vt100 '#{cursor_x},#{cursor_y}')" = 0,0 ]; then pass; else
        fail "TERM=vt100: the cursor should rest at 0,0 (the status line's blank first cell), is at $(tm display -p -t vt100 '#{cursor_x},#{cursor_y}')"
    fi
fi

# ---- v shows or hides a mass's curves; the selected mass is drawn over the others ----
if up hide; then
    keys Space
    wait_t 3 10
    keys Space 1 Tab Down Down # mass 2
    wait_re '└─ mass 2: m' 3
    keys v
    if wait_all 3 "has 'mass 2 hidden in the plots' && [ \"\$(ends)\" = 13 ] && has_re '━1·2━3|━1─·2─━3'"; then
        pass
    else
        fail "v on mass 2 should leave its curve out (ends 13, legend ·2): ends '$(ends)'; screen: $(brief "$scr" 'hidden|━1')"
    fi
    keys v
    if wait_for 'mass 2 shown in the plots' 3 && [ "$(ends)" = 123 ]; then pass; else
        fail "v again should show mass 2 again: ends '$(ends)'; screen: $(brief "$scr" 'shown|━1')"
    fi
    keys Tab v # the controls: no mass selected
    if wait_for 'select it in the chain first' 3; then pass; else
        fail "v with no mass selected should say how to select one; screen: $(brief "$scr")"
    fi
fi
# cells of plot 1 (rows 9 to 27 of 30, left of its frame) in colour $1, from the screen
# as sent: braille characters counted by the colour in force
cells() {
    tm capture-pane -e -p -t "$S" | sed -n '9,27p' | LC_ALL=C awk -v want="$1" '
        BEGIN { esc = sprintf("%c", 27) }
        { fg = "d"; s = $0; col = 0
          while (length(s) > 0 && col < 68) {
              if (substr(s, 1, 2) == esc "[") {
                  e = index(s, "m"); n = split(substr(s, 3, e - 3), a, ";"); s = substr(s, e + 1)
                  for (k = 1; k <= n; k++) {
                      v = a[k] + 0
                      if (v == 0 || v == 39) fg = "d"
                      else if (v >= 30 && v <= 37) fg = v - 30
                      else if (v == 38 && a[k + 1] == 5) { fg = a[k + 2]; k += 2 }
                  }
                  continue
              }
              c = substr(s, 1, 1)
              if (c == "\342" && substr(s, 2, 1) >= "\240" && substr(s, 2, 1) <= "\243") {
                  if (fg == want) count++
                  s = substr(s, 4); col++; continue
              }
              if (c >= "\300") { s = substr(s, 2); while (substr(s, 1, 1) >= "\200" && substr(s, 1, 1) < "\300") s = substr(s, 2); col++; continue }
              s = substr(s, 2); col++
          } }
        END { print count + 0 }'
}
if up top; then
    keys Space
    wait_t 4 10
    keys Space 1
    settle_all 5 "has_re '(▸|>) Paused' && has '0 all plots'"
    c2=$(attr '━2' | sed 's/^fg=\([^ ]*\).*/\1/')
    before=$(cells "$c2")
    keys Tab Down Down # mass 2 selected: drawn last, it keeps the cells it shares
    settle_re '└─ mass 2: m' 3
    after=$(cells "$c2")
    if [ "$before" -gt 0 ] && [ "$after" -gt "$before" ]; then pass; else
        fail "selecting mass 2 should draw it over masses 1 and 3: its cells in plot 1 were $before, are $after (colour $c2)"
    fi
fi

all_alive small ten energy euler fine c8 c8e c256 mono help80 help60 menu120 vt100 hide top
summary
