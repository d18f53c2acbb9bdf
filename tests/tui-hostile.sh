#!/bin/sh
# tests/tui-hostile.sh: the interactive program (tmux) on the largest values it takes
# (issue 23, item 2): every number on the screen in a width, no inf or nan, in the chain
# view, the modes view (m), the energy view (e) and the response view (f).
# Run from the repository root as `sh tests/tui-hostile.sh`, SPRINGSIM naming the binary.
# Ends with "tui-hostile: N passed, M failed".
NAME=tui-hostile
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"

start stiff 120 40 -- -n 2 --spring 1e300 --x0 9
start edge 120 40 -- -n 2 --x0 10,-10 --v0 50,-50
start_shell long 100 10
sessions="stiff edge"

# clean WHAT: the screen in $scr holds no inf, nan and no number of 13 digits or more.
clean() {
    if grep -qiE '(^|[^a-z])-?(inf|nan)([^a-z]|$)|[0-9]{13}' "$scr"; then
        fail "$1: $(grep -oiE '.{0,20}(inf|nan|[0-9]{13}).{0,10}' "$scr" | head -2 | tr '\n' '|')"
    else
        pass
    fi
}

for S in $sessions; do
    if ! wait_re 'Paused'; then
        fail "$S: no first frame: $(brief)"
        continue
    fi
    cap
    clean "$S, the chain view"
    keys Space
    wait_for Running
    # each view, once its frame is up (m again leaves the modes view, and so on)
    for v in 'm:┌─+ Modes' 'm:1 Displacement' 'e:┌─+ Energy' 'e:1 Displacement' 'f:┌─+ (Frequency r|R)esponse'; do
        keys "${v%%:*}"
        wait_re "${v#*:}" 3 || fail "$S: ${v%%:*} should show '${v#*:}'; screen: $(brief)"
        clean "$S, after ${v%%:*}"
    done
done
S=stiff
keys m
if wait_re 'mode 1  1\.592e\+149 Hz'; then pass; else
    fail "stiff: the modes view should title mode 1 '1.592e+149 Hz': $(brief "$scr" 'mode 1')"
fi

# Item 3: a headless run that takes more than a second says how far it has got, on the
# terminal's standard error only, and leaves no line behind when it ends.
S=long
if wait_for 'PROMPT$' 3; then
    keys "'$SPRINGSIM' --headless -n 50 --dt 1e-4 --duration 10000 --sample 1 >/dev/null; echo DONE\$?" Enter
    if wait_re 'springsim: t = [0-9.]+ of 10000 s \([0-9]+ %\)' 10; then pass; else
        fail "a long headless run: no progress line after 10 s: $(brief)"
    fi
    keys C-c
    if wait_re '^PROMPT\$ *$' 10; then pass; else fail "a long headless run: Ctrl-C did not end it: $(brief)"; fi
    keys "clear; '$SPRINGSIM' --headless -n 50 --dt 1e-4 --duration 300 --sample 1 >/dev/null; echo DONE\$?" Enter
    if wait_for 'DONE0' 60; then
        cap
        if grep -q 'springsim: t =' "$scr"; then
            fail "a run that ended left its progress line: $(brief)"
        else pass; fi
    else
        fail "a run of 3e6 steps did not end within 60 s: $(brief)"
    fi
    run --headless --integrator exact -n 20 --duration 3
    if [ "$rc" -eq 0 ] && [ ! -s "$err" ]; then pass; else
        fail "$cmd with standard error not a terminal: exit $rc, stderr $(head -c 200 "$err")"
    fi
else
    fail "no shell prompt: $(brief)"
fi

summary
