#!/bin/sh
# tests/long/storm.sh: the interactive program, running, through 400 random window
# sizes (1x1 and 250x70 among them) as fast as tmux can resize, then a normal size: it
# must still be alive, drawing and answering keys. Ends "storm: N passed, M failed".
NAME=storm
. "$(dirname "$0")/../lib/check.sh"
sock=springsim-storm-$$
T() { tmux -L "$sock" -f /dev/null "$@"; }
cleanup() { T kill-server 2>/dev/null; rm -rf "$tmp"; }

T new-session -d -x 120 -y 40 -s s "env LANG=C.UTF-8 TERM=xterm-256color $SPRINGSIM -p 3-mass-chain; echo EXITED \$?; sleep 60"
T set-option -g window-size manual
sleep 0.5
T send-keys -t s ' '
awk 'BEGIN { srand(42); print "1 1"; print "250 70"; print "2 200";
             for (i = 0; i < 397; i++) print int(1 + rand() * 250), int(1 + rand() * 70) }' |
    while read -r w h; do T resize-window -t s -x "$w" -y "$h"; done
T resize-window -t s -x 120 -y 40
sleep 1
scr=$(T capture-pane -p -t s)
case $scr in *EXITED*) fail "the program died in the storm: $(printf '%s\n' "$scr" | grep EXITED)" ;; *) pass ;; esac
case $scr in *Controls*Displacement*) pass ;; *Displacement*Controls*) pass ;;
*) fail "after the storm the screen is not whole: $(printf '%s\n' "$scr" | head -3)" ;; esac
t1=$(printf '%s\n' "$scr" | sed -n 's/.*t = \([0-9.]*\) s.*/\1/p' | head -1)
sleep 1
t2=$(T capture-pane -p -t s | sed -n 's/.*t = \([0-9.]*\) s.*/\1/p' | head -1)
if awk -v a="$t1" -v b="$t2" 'BEGIN { exit !(b > a) }'; then pass; else
    fail "not running after the storm: t = $t1 then $t2"
fi
T send-keys -t s q
sleep 0.5
case $(T capture-pane -p -t s) in *"EXITED 0"*) pass ;; *) fail "q after the storm did not exit 0" ;; esac
echo "storm: 400 sizes"
summary
