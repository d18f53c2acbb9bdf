#!/bin/sh
# tests/harden-files.sh: hostile preset files and output targets, against the real binary
# ($SPRINGSIM): FIFOs, devices and huge files among the presets; a signal during a run
# where the system has no unnamed files (O_TMPFILE made to fail by a small LD_PRELOAD shim
# built here with cc); a preset path longer than PATH_MAX; section lines with text after
# them and CR-only line ends; an over-long line; the names the interactive program saves
# presets and exports under; -o through dangling symbolic links and loops. Issue 11,
# defects 2, 4, 5, 11, 12, 15 and 18. Ends with "harden-files: N passed, M failed".
NAME=harden-files
. "$(dirname "$0")/lib/check.sh"
XDG_CONFIG_HOME=$tmp/xdg
export XDG_CONFIG_HOME
unset SPRINGSIM_PRESETS

# one_line STATUS NEEDLE ARGS...: exit STATUS within 10 s, one stderr line containing NEEDLE.
one_line() {
    want=$1 needle=$2
    shift 2
    timeout 10 "$SPRINGSIM" "$@" >"$tmp/o" 2>"$tmp/e" </dev/null
    rc=$?
    n=$(awk 'END { print NR }' "$tmp/e")
    if [ "$rc" -eq "$want" ] && [ "$n" -eq 1 ] && grep -qF -- "$needle" "$tmp/e"; then pass; else
        fail "springsim $(echo "$*" | cut -c 1-120): expected exit $want and one line with '$needle'; got exit $rc, $n lines: $(head -c 300 "$tmp/e")"
    fi
}

# ---- 2. Preset directories that could hang it: only regular files are read ----
pd=$tmp/presets
mkdir -p "$pd"
mkfifo "$pd/fifo.ini"
ln -s /dev/zero "$pd/zero.ini"
: >"$pd/huge.ini"
truncate -s 2G "$pd/huge.ini" 2>/dev/null || dd if=/dev/zero of="$pd/huge.ini" bs=1 count=0 seek=2G 2>/dev/null
printf '[preset]\ndescription = The good one\n[system]\nmasses = 2\n' >"$pd/good.ini"
SPRINGSIM_PRESETS=$pd timeout 10 "$SPRINGSIM" --list-presets >"$tmp/list" 2>"$tmp/e"
rc=$?
if [ "$rc" -eq 0 ] && grep -q '^good  *The good one$' "$tmp/list" &&
    ! grep -qE '^(fifo|zero|huge) ' "$tmp/list"; then pass; else
    fail "--list-presets with a FIFO, /dev/zero and a 2 GB file beside good.ini: exit $rc (124: hung), list: $(tr '\n' '|' <"$tmp/list" | head -c 300)"
fi
one_line 1 "fifo.ini: not a regular file" -p "$pd/fifo.ini" --modes
one_line 1 "zero.ini: not a regular file" -p "$pd/zero.ini" --modes
one_line 2 "huge.ini: too large for a preset" -p "$pd/huge.ini" --modes
export SPRINGSIM_PRESETS="$pd"
one_line 1 "not a regular file" -p fifo --modes
unset SPRINGSIM_PRESETS
# the preset menu (p) lists what --list-presets does, without hanging
if command -v tmux >/dev/null 2>&1; then
    have_tmux=1
    . "$(dirname "$0")/lib/tmux.sh"
    mkdir -p "$tmp/exp"
    start menu 120 40 "SPRINGSIM_PRESETS=$pd"
    start save 120 40 "XDG_CONFIG_HOME=$tmp/xdg-save"
    start_in "$tmp/exp" export 120 40
    if up menu; then
        keys p
        if wait_for 'The good one' 5 && lacks 'fifo' && lacks 'zero' && lacks 'huge'; then pass; else
            fail "p with a FIFO, /dev/zero and a 2 GB file among the presets: expected a menu with good only; screen: $(brief "$scr" 'good|fifo|zero|huge')"
        fi
        keys Escape
        keys q
    fi
else
    have_tmux=
    echo "note: tmux is not installed: the preset menu, save and export cases did not run"
fi

# ---- 4. A signal during a run with a named temporary file removes it ----
# The shim makes open(O_TMPFILE) fail as on NFS, vfat or 9p; sigdfl undoes the SIG_IGN
# that a background job of a script starts with, so the signals arrive as from a terminal.
if command -v cc >/dev/null 2>&1; then
    cat >"$tmp/shim.c" <<'EOF'
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
int open(const char *path, int flags, ...);
int open64(const char *path, int flags, ...);
static int pass_on(const char *name, const char *path, int flags, va_list ap)
{
    mode_t mode = (flags & O_CREAT) || (flags & O_TMPFILE) == O_TMPFILE ? va_arg(ap, mode_t) : 0;
    if ((flags & O_TMPFILE) == O_TMPFILE) {
        errno = EOPNOTSUPP;
        return -1;
    }
    int (*real)(const char *, int, ...) = (int (*)(const char *, int, ...))dlsym(RTLD_NEXT, name);
    return real(path, flags, mode);
}
int open(const char *path, int flags, ...)
{
    va_list ap;
    va_start(ap, flags);
    int fd = pass_on("open", path, flags, ap);
    va_end(ap);
    return fd;
}
int open64(const char *path, int flags, ...)
{
    va_list ap;
    va_start(ap, flags);
    int fd = pass_on("open64", path, flags, ap);
    va_end(ap);
    return fd;
}
EOF
    cat >"$tmp/sigdfl.c" <<'EOF'
#include <signal.h>
#include <stdio.h>
#include <unistd.h>
int main(int argc, char **argv)
{
    (void)argc;
    signal(SIGINT, SIG_DFL);
    signal(SIGHUP, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    execvp(argv[1], argv + 1);
    perror(argv[1]);
    return 127;
}
EOF
    if cc -shared -fPIC -o "$tmp/shim.so" "$tmp/shim.c" -ldl 2>"$tmp/cc.err" &&
        cc -o "$tmp/sigdfl" "$tmp/sigdfl.c" 2>>"$tmp/cc.err"; then
        mkdir -p "$tmp/nt"
        # Under AddressSanitizer its runtime must be the first library preloaded.
        preload=$tmp/shim.so
        asan=$(ldd "$SPRINGSIM" 2>/dev/null | awk '/libasan/ { print $3; exit }')
        [ -n "$asan" ] && preload="$asan $preload"
        for sig in INT:2 TERM:15 HUP:1; do
            num=${sig#*:} sig=${sig%:*}
            printf 'old\n' >"$tmp/nt/out.csv"
            LD_PRELOAD=$preload "$tmp/sigdfl" "$SPRINGSIM" --headless -n 200 \
                --duration 100000 -o "$tmp/nt/out.csv" 2>"$tmp/nt.err" &
            pid=$!
            i=0 # until the fallback's named temporary file is there
            while [ $i -lt 50 ] && ! ls "$tmp/nt" | grep -q 'out.csv.tmp-'; do
                sleep 0.1
                i=$((i + 1))
            done
            if ! ls "$tmp/nt" | grep -q 'out.csv.tmp-'; then
                fail "SIG$sig: no out.csv.tmp-XXXXXX appeared with O_TMPFILE failing (the shim did not act?)"
                kill -9 "$pid" 2>/dev/null
                wait "$pid" 2>/dev/null
                continue
            fi
            kill -"$sig" "$pid"
            wait "$pid" 2>/dev/null
            rc=$?
            want=$((128 + num))
            left=$(ls "$tmp/nt" | grep 'out.csv.tmp-' | tr '\n' ' ')
            if [ -z "$left" ] && [ "$rc" -eq "$want" ] && [ "$(cat "$tmp/nt/out.csv")" = old ]; then
                pass
            else
                fail "SIG$sig during -o without O_TMPFILE: expected death by the signal ($want), no temporary file and the old content; got exit $rc, left: '$left', out.csv: $(head -c 40 "$tmp/nt/out.csv")"
            fi
            rm -f "$tmp/nt"/out.csv.tmp-*
        done
        # and a run that completes still replaces the file whole
        LD_PRELOAD=$preload "$SPRINGSIM" --headless --duration 1 -o "$tmp/nt/out.csv" &&
            [ "$(wc -l <"$tmp/nt/out.csv")" -eq 102 ] && [ -z "$(ls "$tmp/nt" | grep tmp-)" ] &&
            pass || fail "without O_TMPFILE a complete run should write 102 lines and leave no temporary file"
    else
        fail "cannot build the O_TMPFILE shim: $(head -c 300 "$tmp/cc.err")"
    fi
else
    echo "note: no C compiler: the O_TMPFILE fallback was not tested"
fi

# ---- 5. A preset path longer than PATH_MAX is refused, not cut to another file ----
# The first 4095 bytes of the long path name a real preset: cut there, it would load.
mkdir -p "$tmp/p5"
printf '[system]\nmasses = 3\n' >"$tmp/p5/real.ini"
long=$(awk -v d="$tmp/p5" 'BEGIN {
    s = d "/"; tail = "real.ini"
    while (length(s) + length(tail) + 2 <= 4095) s = s "./"
    while (length(s) + length(tail) < 4095) s = s "/"
    printf "%s%sxyz/more.ini", s, tail }')
one_line 2 "too long for a file name" -p "$long" --modes
if [ ! -s "$tmp/o" ]; then pass; else fail "an over-long preset path still ran: $(head -c 100 "$tmp/o")"; fi

# ---- 11. INI syntax inih lets through ----
printf '[system] junk\nmasses = 2\n' >"$tmp/junk.ini"
one_line 2 "junk.ini:1: text after the section header [system]" -p "$tmp/junk.ini" --modes
printf '[system] ; a comment is fine\nmasses = 2\n' >"$tmp/comment.ini"
one_line_ok() { # ARGS...: exit 0, nothing on stderr
    timeout 10 "$SPRINGSIM" "$@" >"$tmp/o" 2>"$tmp/e" </dev/null
    rc=$?
    if [ "$rc" -eq 0 ] && [ ! -s "$tmp/e" ]; then pass; else
        fail "springsim $*: expected exit 0 and no message; got $rc: $(head -c 200 "$tmp/e")"
    fi
}
one_line_ok -p "$tmp/comment.ini" --modes
printf '[system]\rmasses = 2\rmass = abc\r' >"$tmp/cr.ini"
one_line 2 "cr.ini:3: mass: 'abc' is not a number" -p "$tmp/cr.ini" --modes
printf '[system]\rmasses = 3\r' >"$tmp/crgood.ini"
one_line_ok -p "$tmp/crgood.ini" --modes
if [ "$(awk 'END { print NR }' "$tmp/o")" -eq 4 ]; then pass; else
    fail "a CR-only preset with masses = 3: expected 3 modes, got: $(tr '\n' '|' <"$tmp/o")"
fi
printf '[system]\r\nmasses = 3\r\n' >"$tmp/crlf.ini"
one_line_ok -p "$tmp/crlf.ini" --modes

# ---- 12. An over-long line names its key and says how a list goes on ----
awk 'BEGIN { printf "[system]\nmass = "; for (i = 0; i < 5000; i++) printf "9"; print "" }' \
    >"$tmp/digits.ini"
one_line 2 "digits.ini:2: line is longer than 198 characters, in the value of 'mass'" \
    -p "$tmp/digits.ini" --modes
if grep -q "indented lines" "$tmp/e"; then pass; else fail "the long-line message should say how to continue a list: $(cat "$tmp/e")"; fi
awk 'BEGIN { printf "[system]\nmasses = 2\nmass = 1,\n    "; for (i = 0; i < 300; i++) printf "2"; print "" }' \
    >"$tmp/cont.ini"
one_line 2 "cont.ini:4: line is longer than 198 characters, in a continuation of 'mass'" \
    -p "$tmp/cont.ini" --modes

# ---- 18. -o through symbolic links ----
mkdir -p "$tmp/o18"
ln -s target.csv "$tmp/o18/dangling.csv"
one_line_ok --headless --duration 0.1 -o "$tmp/o18/dangling.csv"
if [ -L "$tmp/o18/dangling.csv" ] && [ -f "$tmp/o18/target.csv" ] &&
    [ "$(wc -l <"$tmp/o18/target.csv")" -eq 12 ]; then pass; else
    fail "-o to a dangling link: expected the link kept and target.csv written (12 lines); found: $(ls -l "$tmp/o18" | tr '\n' '|')"
fi
ln -s nodir/x.csv "$tmp/o18/nodir.csv"
one_line 1 "No such file or directory" --headless --duration 0.1 -o "$tmp/o18/nodir.csv"
if [ -L "$tmp/o18/nodir.csv" ]; then pass; else fail "-o to a link into a missing directory replaced the link"; fi
ln -s loop-b "$tmp/o18/loop-a"
ln -s loop-a "$tmp/o18/loop-b"
one_line 1 "loop-a: Too many levels of symbolic links" --headless --duration 0.1 -o "$tmp/o18/loop-a"
if [ -L "$tmp/o18/loop-a" ] && [ -L "$tmp/o18/loop-b" ] &&
    [ "$(ls "$tmp/o18" | grep -c .)" -eq 5 ]; then pass; else
    fail "-o to a link loop changed the directory: $(ls -l "$tmp/o18" | tr '\n' '|')"
fi
ln -s loop-a "$tmp/o18/to-loop"
one_line 1 "Too many levels of symbolic links" --modes -o "$tmp/o18/to-loop"
# a chain of links ending nowhere, relative and absolute
ln -s "$tmp/o18/hop2" "$tmp/o18/hop1"
ln -s end.csv "$tmp/o18/hop2"
one_line_ok --modes -o "$tmp/o18/hop1"
if [ -L "$tmp/o18/hop1" ] && [ -L "$tmp/o18/hop2" ] && grep -q '^mode,' "$tmp/o18/end.csv"; then pass; else
    fail "-o through two links to a missing file: expected end.csv written; found: $(ls -l "$tmp/o18" | tr '\n' '|')"
fi

# ---- A replaced file keeps its owner and group (root writing over a user's file) ----
if [ "$(id -u)" = 0 ]; then
    mkdir -p "$tmp/own"
    echo old >"$tmp/own/theirs.csv"
    chown 4242:4343 "$tmp/own/theirs.csv"
    chmod 640 "$tmp/own/theirs.csv"
    one_line_ok --headless --duration 0.1 -o "$tmp/own/theirs.csv"
    got=$(stat -c '%u:%g %a' "$tmp/own/theirs.csv")
    if [ "$got" = "4242:4343 640" ] && grep -q '^t,' "$tmp/own/theirs.csv"; then pass; else
        fail "-o as root over a file of 4242:4343, mode 640: expected it kept, got $got"
    fi
    printf 'quit\n' >"$tmp/own/quit"
    echo old >"$tmp/own/theirs.lesson"
    chown 4242:4343 "$tmp/own/theirs.lesson"
    "$SPRINGSIM" --plain --record "$tmp/own/theirs.lesson" <"$tmp/own/quit" >/dev/null 2>&1
    got=$(stat -c '%u:%g' "$tmp/own/theirs.lesson")
    [ "$got" = "4242:4343" ] && pass ||
        fail "--record as root over a file of 4242:4343: the owner became $got"
fi

# ---- 15 and 18 in the interactive program: save as x.ini, two exports at once ----
if [ -n "$have_tmux" ]; then
    S=save
    if up save; then
        keys s
        if wait_for 'save preset as' 3; then
            text x.ini
            keys Enter
            if wait_for 'springsim -p x loads it' 3 && [ -f "$tmp/xdg-save/springsim/presets/x.ini" ] &&
                [ ! -e "$tmp/xdg-save/springsim/presets/x.ini.ini" ]; then pass; else
                fail "save as x.ini: expected x.ini and the hint '-p x'; screen: $(brief); files: $(ls "$tmp/xdg-save/springsim/presets" 2>&1 | tr '\n' ' ')"
            fi
            XDG_CONFIG_HOME=$tmp/xdg-save
            one_line_ok -p x --modes
            XDG_CONFIG_HOME=$tmp/xdg
        else
            fail "save: s did not ask for a name; screen: $(brief)"
        fi
        keys q
    fi
    S=export
    if up export; then
        keys x x x
        sleep 1
        n=$(ls "$tmp/exp" | grep -c '^springsim-.*\.csv$')
        if [ "$n" -eq 3 ]; then pass; else
            fail "x x x: expected three export files, found $n: $(ls "$tmp/exp" | tr '\n' ' ')"
        fi
        keys q
    fi
fi

summary
