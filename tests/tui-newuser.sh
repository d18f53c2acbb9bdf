#!/bin/sh
# tests/tui-newuser.sh: what a new user met (issue 22), as a person sees it in tmux: at
# 60x20 the controls scroll to the selection and the frame says how many are out of
# sight; with ten masses at 80x24 the legends and the natural frequencies end in "…"
# and keep the motor; the energy view's drift is never cut; while dt is past a limit the
# status line says so after the warning has gone. Run from the repository root as
# `sh tests/tui-newuser.sh`, SPRINGSIM naming the binary. Ends with "tui-newuser: N
# passed, M failed".
NAME=tui-newuser
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"

start small 60 20 -- -p 3-mass-chain
start ten 80 24 -- -n 10 --random --seed 5
start energy 60 20 -- -p 3-mass-chain
start euler 80 24 -- --integrator euler --dt 0.05
start fine 80 24 -- -p 3-mass-chain

# row N of the screen, and the controls' frame (the right-hand column from its corner)
row() { sed -n "${1}p" "$scr"; }
controls() { LC_ALL=$U8 sed -n '/┌ Controls/,/^.*┘$/p' "$scr" | LC_ALL=$U8 sed 's/.*\(┌ Controls\)/\1/; s/.*││//; s/.*┘└/└/'; }

# ---- 60x20: 14 controls in 12 rows ----
if up small; then
    if has_re '└─+ ↓ 2 more ─┘' && lacks '↑ 2 more' && has 'Frequency' && lacks 'Refresh'; then
        pass
    else
        fail "60x20: the controls' frame should say '↓ 2 more' below Frequency; screen: $(brief "$scr" 'more|Frequency')"
    fi
    keys Up # wraps to the last control, Refresh
    if wait_re '▸Refresh +normal' 3 && has_re 'Controls ─+ ↑ 2 more ─┐' && has 'Speed' &&
        lacks '↓ 2 more' && lacks 'Preset '; then
        pass
    else
        fail "60x20: ↑ from Preset should scroll to ▸Refresh, Speed above it, the frame saying '↑ 2 more'; screen: $(brief "$scr" 'more|Refresh|Speed')"
    fi
    keys Down # wraps to Preset: the list scrolls back
    if wait_re '▸Preset' 3 && has '↓ 2 more' && lacks '↑ 2 more'; then pass; else
        fail "60x20: ↓ from Refresh should scroll back to ▸Preset; screen: $(brief "$scr" 'more|Preset')"
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
    if wait_re '│ drift [0-9.]+e[-+][0-9]+ of the peak +│' 3 && has_re '━kin [0-9.e+-]+ ━pot' &&
        has_re '━damp [0-9.e+-]+ ━motor [0-9.e+-]+ +… │'; then
        pass
    else
        fail "60x20 energy view: brief names ('━kin', '━pot', '━damp', '━motor', then '…') and the whole 'drift … of the peak' line; screen: $(brief "$scr" 'drift|━')"
    fi
fi

# ---- dt past a limit: the status line says so while it is ----
if up euler; then
    wait_re 'unstable' 3
    keys Space
    sleep 1
    cap
    if row 1 | grep -qE '(Running|Paused) t = [0-9.]+ s │ dt unstable │' && ! row 24 | grep -q 'unstable with'; then
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

all_alive small ten energy euler fine
summary
