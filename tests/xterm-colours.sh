#!/bin/sh
# tests/xterm-colours.sh: one colour a mass, measured in a real xterm (xterm -ti vt340,
# sixel) on a virtual X screen (Xvfb): with TERM=xterm (8 colours) and TERM=xterm-256color,
# in the time plots (after 8 s, the masses moved apart from the drive's line), the energy
# view and the response view, each legend mark's colour on the screenshot is within
# delta E 10 of pixels of its chart's image (tests/lib/xcolours.py;
# the program run through tests/lib/xfeed.py, which records what it wrote and the answers).
# Ends with "xterm-colours: N passed, M failed".
NAME=xterm-colours
. "$(dirname "$0")/lib/check.sh"
lib=$(cd "$(dirname "$0")/lib" && pwd)
for tool in Xvfb xterm import identify convert; do
    if ! command -v $tool >/dev/null 2>&1; then
        fail "$tool is not installed (mk/deps.sh test installs it); no colour was measured"
        summary
        exit
    fi
done
plain_env
LC_ALL=C.UTF-8
export LC_ALL
Xvfb -displayfd 3 -screen 0 1400x900x24 -nolisten tcp 3>"$tmp/display" >/dev/null 2>&1 &
xvfb=$!
cleanup() { kill "$xvfb" 2>/dev/null; rm -rf "$tmp"; }
n=0
while [ ! -s "$tmp/display" ] && [ $n -lt 50 ]; do sleep 0.1; n=$((n + 1)); done
DISPLAY=:$(cat "$tmp/display")
export DISPLAY

# shot TERM KEYS ARGS...: the program in xterm, KEYS typed up to '!' (then the screenshot,
# then the rest); the files in $tmp/x.
shot() {
    term=$1 keys=$2
    shift 2
    rm -rf "$tmp/x"
    mkdir -p "$tmp/x"
    xterm -ti vt340 -fa 'DejaVu Sans Mono' -fs 9 -geometry 120x40+0+0 -bg white -fg black \
        -xrm 'XTerm*decTerminalID: vt340' -xrm 'XTerm*numColorRegisters: 256' \
        -e env TERM="$term" /usr/bin/python3 "$lib/xfeed.py" "$tmp/x" "$keys" "$SPRINGSIM" "$@" \
        >/dev/null 2>&1 &
    xt=$!
    n=0
    while [ ! -e "$tmp/x/ready" ] && [ $n -lt 300 ]; do sleep 0.1; n=$((n + 1)); done
    import -window root "$tmp/x/shot.png" 2>/dev/null
    touch "$tmp/x/go"
    n=0
    while kill -0 "$xt" 2>/dev/null && [ $n -lt 100 ]; do sleep 0.1; n=$((n + 1)); done
    kill "$xt" 2>/dev/null
}

for term in xterm xterm-256color; do
    for view in "plots: ~~~~~~~~ ~!q" "energy:e ~~~ ~!q" "response:f~~~!q"; do
        name=${view%%:*} keys=${view#*:}
        shot "$term" "$keys" -n 3
        if [ ! -s "$tmp/x/shot.png" ]; then
            fail "TERM=$term, $name: no screenshot"
            continue
        fi
        if /usr/bin/python3 "$lib/xcolours.py" "$tmp/x" 120 40 >"$tmp/marks" 2>&1 &&
            [ "$(wc -l <"$tmp/marks")" -ge 3 ]; then pass; else
            fail "TERM=$term, $name: legend marks against their images: $(tr '\n' '|' <"$tmp/marks")"
        fi
        echo "xterm-colours: TERM=$term $name: $(tr '\n' ' ' <"$tmp/marks")" >&2
    done
done

summary
