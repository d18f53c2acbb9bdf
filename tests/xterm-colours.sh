#!/bin/sh
# tests/xterm-colours.sh: one colour a mass, measured in a real xterm (xterm -ti vt340,
# sixel) on a virtual X screen (Xvfb): with TERM=xterm (8 colours) and TERM=xterm-256color,
# in the time plots, the energy view and the response view, each legend mark's colour on
# the screenshot is within delta E 10 of its own curve's colour in its chart's image
# (tests/lib/xcolours.py; the program run through tests/lib/xfeed.py, which records what
# it wrote and the answers). The runs keep the curves apart, so that each one's pixels
# are known by their place: in the time plots three free masses (springs of 0.001 N/m,
# no damping) at three heights moving at three speeds, the motor's swing between them;
# in the energy view five terms at five levels (a heavy mass held off by a spring, a free
# heavy one moving, a light one stopped by its damper, the motor pushing it through a
# spring, no contact); in the response view the amplitudes above 1 Hz, mass 3's highest,
# and the drive's upright line. Measured against a wrong order, the same screenshot fails.
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

# The runs (see the top) and how each chart's curves are told apart (xcolours.py's SPEC).
PLOTS="-n 3 --spring 0.001 --damping 0 --x0 0.4,0.2,-0.3 --v0 0.02,0.005,-0.01"
ENERGY="-n 3 --spring 10,0,0,10 --mass 10000,100,1 --damping 0,0,10 --x0 0.7,0,0
    --v0 0,0.155,-2.6 --amplitude 0.18 --no-collisions"
plots_spec="Displacement=1,2,motor,3 Velocity=1,2,3"
energy_spec="Energy@15-100=damped,potential,kinetic,motor,contact"
response_spec="amplitude@62-75=3,2,1 amplitude=|drive"

# judge TERM NAME SPECS: the marks of the last shot against their curves.
judge() {
    if /usr/bin/python3 "$lib/xcolours.py" "$tmp/x" 120 40 $3 >"$tmp/marks" 2>&1 &&
        [ "$(wc -l <"$tmp/marks")" -ge 3 ]; then pass; else
        fail "TERM=$1, $2: legend marks against their curves: $(tr '\n' '|' <"$tmp/marks")"
    fi
    echo "xterm-colours: TERM=$1 $2: $(tr '\n' ' ' <"$tmp/marks")" >&2
}

for term in xterm xterm-256color; do
    for view in "plots: ~~~~~~~~ ~!q" "energy:e ~~~~ ~!q" "response:f~~~!q"; do
        name=${view%%:*} keys=${view#*:}
        case $name in
        plots) args=$PLOTS spec=$plots_spec ;;
        energy) args=$ENERGY spec=$energy_spec ;;
        *) args="-n 3" spec=$response_spec ;;
        esac
        shot "$term" "$keys" $args
        if [ ! -s "$tmp/x/shot.png" ]; then
            fail "TERM=$term, $name: no screenshot"
            continue
        fi
        judge "$term" "$name" "$spec"
        # The check can fail: masses 1 and 2 taken for each other.
        if [ "$term $name" = "xterm-256color plots" ]; then
            /usr/bin/python3 "$lib/xcolours.py" "$tmp/x" 120 40 "Displacement=2,1,motor,3" \
                >"$tmp/swapped" 2>&1
            [ $? -eq 1 ] && [ "$(grep -c '^[12] .*FAIL' "$tmp/swapped")" -ge 2 ] && pass ||
                fail "masses 1 and 2 swapped should fail: $(tr '\n' '|' <"$tmp/swapped")"
        fi
    done
done

summary
