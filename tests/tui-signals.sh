#!/bin/sh
# tests/tui-signals.sh: every way out of the interactive program gives the terminal back
# (springsim(1), INTERACTIVE PROGRAM): q (at 120x40 and 80x24), Ctrl-C (running, and with the help open),
# SIGTERM, SIGHUP and a crash (SIGSEGV), each with the status it should give; the
# terminal modes (stty -g) afterwards are those before, the program's screen gone.
# Run from the repository root as `sh tests/tui-signals.sh`, SPRINGSIM naming the
# binary. Ends with "tui-signals: N passed, M failed".
NAME=tui-signals
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"

cases="q TERM HUP INT SEGV INT-help"
for c in $cases; do start "sig-$c" 120 40; done
start sig-q-small 80 24

how() {
    case $1 in
    q*) echo q ;; INT*) echo Ctrl-C ;; SEGV) echo "a crash (SIGSEGV)" ;; *) echo "SIG$1" ;;
    esac
}
sent=
for c in $cases q-small; do
    if ! up "sig-$c"; then continue; fi
    case $c in
    *-help)
        keys '?'
        wait_for 'preset menu' || fail "$(how "$c") with the help open: ? did not open it; screen: $(brief)"
        ;;
    *)
        keys Space
        wait_for Running || fail "$(how "$c") while running: space did not start it; screen: $(brief)"
        ;;
    esac
    sent="$sent $c"
    case $c in
    q*) keys q ;;
    INT*) keys C-c ;;
    *) kill "-$c" "$(cat "$tmp/sig-$c.pid")" ;;
    esac
done
for c in $sent; do
    S=sig-$c
    h=$(how "$c")
    case $c in
    q*) want='EXITED 0' ;; INT*) want='EXITED 130' ;; TERM) want='EXITED 143' ;;
    HUP) want='EXITED 129' ;; SEGV) want="EXITED [1-9][0-9]*" ;;
    esac
    if wait_for 'TERMINAL '; then
        if ! has_re "^$want\$"; then
            fail "quit by $h ($c): expected '$want'; screen: $(brief "$scr" 'EXITED|TERMINAL')"
        elif ! has 'TERMINAL SAME'; then
            fail "quit by $h ($c): the terminal modes (stty -g) differ after exit; screen: $(brief "$scr" 'EXITED|TERMINAL')"
        elif has_re '━|┌|Controls'; then
            fail "quit by $h ($c): the program's screen should be gone (alternate screen left); screen: $(brief)"
        else
            pass
        fi
    else
        fail "quit by $h ($c): expected the program to exit within 5 s; screen: $(brief)"
    fi
done

summary
