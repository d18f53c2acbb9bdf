#!/bin/sh
# tests/tui-modes.sh: the live modes view and the response view's phase panel in a real
# terminal (tmux), checked against closed forms where there are some:
# - m: every mode's damping ratio and Q; with equal masses and dampers the damping is
#   proportional, so zeta_j = c / (2 m w_j) and Q = 1 / (2 zeta) exactly;
# - the shapes swing while paused (two frames differ), and stop being drawn the same;
# - Enter on mode 2 starts the chain in it: mode 2 has 100 % of the energy, the others 0 %;
# - f: the phase panel, -180..180 degrees, and one mass driven below, at and above its
#   natural frequency lags by atan2(c w, k1 + k2 - m w^2): about 0, 90 and 180 degrees;
# - a mode damped past zeta = 1/sqrt(2) has no resonant peak: said, and no -3 dB band.
# Run from the repository root as `sh tests/tui-modes.sh`, SPRINGSIM naming the binary.
# Ends with "tui-modes: N passed, M failed".
NAME=tui-modes
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"

start zeta 120 40 -- -p 3-mass-chain --damping 0.3
start enter 120 40 -- -p 3-mass-chain --amplitude 0
start below 120 40 -- -n 1 --frequency 0.3
start at 120 40 -- -n 1 --frequency 0.7118
start above 120 40 -- -n 1 --frequency 2
start small 80 24 -- -p 3-mass-chain
start heavy 120 40 -- -n 1 --damping 7
start six 60 20 -- -n 6
start wallend 120 40 -- -p 3-mass-chain --boundary wall
start sweeping 120 40 -- -p 3-mass-chain
start amp0 120 40 -- -p 3-mass-chain --amplitude 0
sessions="zeta enter below at above small heavy six wallend sweeping amp0"

# ---- m: zeta and Q against the closed form ----
# zeta_bad: what on the screen disagrees with zeta_j = c / (2 m w_j), Q = 1 / (2 zeta)
# (c = 0.3, m = 1); empty when all three modes agree. The titles "mode J  F Hz" and the
# rows "ζ Z  Q Q" come in the same order (row by row, left to right): the k-th of each
# belong to one mode.
zeta_bad() {
    grep -oE 'mode [0-9]+  [0-9.]+ Hz' "$scr" | awk '{ print $3 }' >"$tmp/zeta.f"
    grep -oE 'ζ [0-9.e-]+  Q [0-9.]+' "$scr" | awk '{ print $2, $4 }' >"$tmp/zeta.z"
    paste -d ' ' "$tmp/zeta.f" "$tmp/zeta.z" | awk -v c=0.3 -v m=1 '
        function off(a, b) { return (a - b) / b > 0.01 || (b - a) / b > 0.01 }
        {
            pi = atan2(0, -1); want = c / (2 * m * 2 * pi * $1); seen++
            if (NF != 3 || off($2, want) || off($3, 0.5 / want))
                printf "mode at %s Hz: zeta %s Q %s, expected zeta %.4g Q %.4g; ", $1, $2, $3, want, 0.5 / want
        }
        END { if (seen != 3) printf "found %d modes with zeta and Q, expected 3", seen }'
}
zeta_ok() { [ -z "$(zeta_bad)" ]; }
if up zeta; then
    keys m
    if poll 3 zeta_ok; then pass; else
        fail "modes view zeta/Q: $(zeta_bad); screen: $(brief "$scr" 'mode|ζ')"
    fi
    # The shapes swing while paused: the picture changes from one refresh to another.
    cp "$scr" "$tmp/zeta.a"
    differs() { ! cmp -s "$tmp/zeta.a" "$scr"; }
    if poll 2 differs && has Paused; then pass; else
        fail "modes view: the shapes should swing while paused; the screen stayed the same for 2 s"
    fi
fi

# ---- Enter: the chain started in mode 2 is all mode 2 ----
if up enter; then
    keys m Down Enter
    # the 100 % bar is in mode 2's cell (its row, two below its title), the others are 0
    shares_ok() {
        shares=$(grep -oE '[0-9]+ %' "$scr" | tr -d ' %' | tr '\n' ' ')
        rows=$(awk '/mode 2  0\.712 Hz/ { print NR }' "$scr")
        [ "$shares" = "0 100 0 " ] && [ -n "$rows" ] &&
            sed -n "$((rows + 2))p" "$scr" | grep -qE '100 %'
    }
    if wait_re 'started in mode 2' 3 && wait_t 2 && wait_re '100 %' 3; then
        if poll 2 shares_ok; then pass; else
            fail "Enter on mode 2: expected shares 0 100 0 with 100 % under mode 2, got '$shares'; screen: $(brief "$scr" 'mode|%')"
        fi
        if has Running; then pass; else fail "Enter on a mode should start the chain running"; fi
    else
        fail "Enter on mode 2 (m Down Enter): expected 'started in mode 2' and a 100 % bar; screen: $(brief)"
    fi
fi

# ---- f: the phase panel ----
# phase_is SESSION DEG: the legend names mass 1's phase within 2 degrees of DEG.
phase_is() {
    got=$(sed -n 's/.*at [0-9.]* Hz─1 \(-\{0,1\}[0-9]*\)°.*/\1/p' "$scr" | head -n 1)
    awk -v g="$got" -v w="$2" 'BEGIN { d = g - w; exit !(g != "" && d <= 2 && d >= -2) }' ||
        { fail "phase ($1): mass 1 should lag by about $2 degrees, legend says '$got'; screen: $(brief "$scr" 'Phase|at ')"; return; }
    pass
}
for s in below at above; do
    if up $s; then
        keys f
        if settle_for 'Phase of each mass to the drive' 3; then
            for label in 180 90 0 -90 -180; do
                if has_re "│ +$label┤"; then pass; else fail "phase ($s): no tick label $label; screen: $(brief "$scr" 'Phase|┤')"; fi
            done
            # atan2(-c w, k1 + k2 - m w^2) with c = 0.1, k = 10, m = 1
            want=$(awk -v f="$(case $s in below) echo 0.3 ;; at) echo 0.7118 ;; *) echo 2 ;; esac)" \
                'BEGIN { pi = atan2(0, -1); w = 2 * pi * f; printf "%.0f", atan2(-0.1 * w, 20 - w * w) * 180 / pi }')
            phase_is $s "$want"
        else
            fail "f ($s): expected the phase panel under the response; screen: $(brief)"
        fi
    fi
done

# ---- 80x24: both views still show what matters ----
if up small; then
    keys m
    if wait_all 3 "has_re 'mode 3  0\.930 Hz' && has_re 'Q [0-9]'"; then pass; else
        fail "modes view at 80x24: all three modes with Q; screen: $(brief)"
    fi
    keys m f
    if settle_all 3 "has_re 'Phase' && has_re '│ +-180┤'"; then pass; else
        fail "response at 80x24: the phase panel should show; screen: $(brief)"
    fi
fi

# ---- zeta = c / (2 sqrt(k m)) = 7 / (2 sqrt(20)) = 0.783: no peak, no -3 dB band ----
if up heavy; then
    keys m
    if wait_all 3 "has_re 'ζ 0\.783  Q 0\.639  no resonant peak' && lacks '-3 dB'"; then pass; else
        fail "modes view with zeta 0.783: expected 'ζ 0.783  Q 0.639  no resonant peak' and no '-3 dB'; screen: $(brief "$scr" 'ζ')"
    fi
fi

# ---- 60x20, six modes on one row each: the rows left over give every mode its bar ----
if up six; then
    keys m Space
    bars_ok() { [ "$(grep -cE '│ E .*%' "$scr")" -ge 5 ]; }
    if poll 3 bars_ok; then pass; else
        fail "modes view at 60x20 with 6 masses: each mode (but one) should get its energy bar; screen: $(brief "$scr" 'mode|E ')"
    fi
fi

# ---- a wall end does not drive: no mode mark on the Frequency control ----
if up wallend; then
    keys m
    if wait_all 3 "has_re 'mode 3  0\.930 Hz' && has_re 'Frequency +0\.712 Hz' && ! has_re 'Frequency.*◆'"; then pass; else
        fail "wall end: the Frequency control should not say it drives a mode; screen: $(brief "$scr" 'Frequency')"
    fi
fi

# ---- Enter during a sweep says the sweep stopped ----
if up sweeping; then
    keys w
    if wait_re 'sweeping' 3; then
        keys m Down Enter
        if wait_re 'sweep stopped; started in mode 2' 3; then pass; else
            fail "Enter on a mode during a sweep should say the sweep stopped; screen: $(brief)"
        fi
    else
        fail "w should start a sweep; screen: $(brief)"
    fi
fi

# ---- no drive: the response view says why, with no empty axes under the words ----
if up amp0; then
    keys f
    if settle_all 3 "has \"The motor's amplitude is 0\" && ! has_re '1e-?[0-9]+┤|└┬|│ +-?[0-9]+┤'"; then pass; else
        fail "response view without a drive: the reason alone, no axes; screen: $(brief "$scr" 'amplitude|┤|└')"
    fi
fi

all_alive $sessions
summary
