# tests/lib/tmux.sh: the interactive program in a real terminal, for the terminal tests.
# Source it after tests/lib/check.sh (which gives $tmp, pass, fail and summary).
#
# Everything runs on a private tmux server (tmux -u -L springsim-NAME-PID -f /dev/null),
# killed at exit; the user's own tmux server is never touched. Each case runs in a session
# of its own, started at the top of a script so that they all run at once.
#
#   start NAME COLS ROWS [VAR=VALUE]... [-- ARG...]   the program in a new session, in a
#                       UTF-8 locale with TERM=xterm-256color (VAR=VALUE override those)
#   start_in DIR NAME COLS ROWS ...                   the same, working directory DIR
#   start_shell NAME COLS ROWS                        an interactive sh (prompt "PROMPT$ ")
#   S=NAME              the session the helpers below work on
#   keys KEY...         tmux send-keys (key names: Space, Enter, C-c, Up, PgDn, ...)
#   text STRING         the characters of STRING, literally
#   cap                 the screen, as a person sees it, into $scr (cap_raw: as sent)
#   has TEXT, has_re REGEX, lacks TEXT                about $scr
#   poll SECONDS CMD [ARG...]                         THE one waiting loop: captures the
#                       screen every 0.1 s until CMD succeeds, false after SECONDS
#   wait_for TEXT [S], wait_re REGEX [S], wait_gone TEXT [S], wait_same FILE [S],
#   wait_t T [S]        poll for the usual things (default 5 s)
#   brief [FILE] [REGEX]  a few lines of a screen for a failure message
#   alive NAME          the program of session NAME is still running
#
# Every program pane runs pane.sh, which records the terminal modes, runs the program (its
# pid in $tmp/NAME.pid) and, once it ends, shows "EXITED status" and "TERMINAL SAME" or
# "TERMINAL CHANGED" (whether stty -g is what it was before).

if ! command -v tmux >/dev/null 2>&1; then
    fail "tmux is not installed (mk/deps.sh test installs it); no test of the interactive program ran"
    summary
    exit
fi
if ! [ -x "$SPRINGSIM" ] && ! command -v "$SPRINGSIM" >/dev/null 2>&1; then
    fail "no program at SPRINGSIM=$SPRINGSIM"
    summary
    exit
fi

# A UTF-8 locale for the program's UTF-8 runs and for tmux itself.
U8=$(locale -a 2>/dev/null | grep -iE '^(C|en_US)\.utf-?8$' | head -n 1)
[ -n "$U8" ] || U8=C.UTF-8
LC_ALL=$U8
export LC_ALL

SOCK=springsim-$NAME-$$
tm() { LC_ALL=$U8 LANG=$U8 tmux -u -L "$SOCK" -f /dev/null "$@"; }

sockpath=
# cleanup: the server killed, then its programs waited for (2 s at most: a program may
# still be writing into $tmp as the hang-up ends it) before $tmp goes.
cleanup() {
    tm kill-server >/dev/null 2>&1
    [ -n "$sockpath" ] && rm -f "$sockpath"
    cl_n=0
    while [ $cl_n -lt 20 ]; do
        cl_alive=
        for cl_p in "$tmp"/*.pid; do
            [ -s "$cl_p" ] && kill -0 "$(cat "$cl_p")" 2>/dev/null && cl_alive=1
        done
        [ -z "$cl_alive" ] && break
        sleep 0.1
        cl_n=$((cl_n + 1))
    done
    rm -rf "$tmp"
}
trap cleanup EXIT
trap 'exit 1' HUP INT TERM

# The program never sees the user's presets or tmux.
mkdir -p "$tmp/xdg"
unset SPRINGSIM_PRESETS SPRINGSIM_LESSONS NO_COLOR COLORTERM TMUX TMUX_PANE

ESC=$(printf '\033')

# pane.sh DIR BINARY NAME [VAR=VALUE]... -- [ARG]...
cat >"$tmp/pane.sh" <<'EOF'
dir=$1 bin=$2 name=$3
shift 3
unset SPRINGSIM_PRESETS SPRINGSIM_LESSONS LC_CTYPE LC_MESSAGES LC_NUMERIC LANGUAGE NO_COLOR COLORTERM
while [ $# -gt 0 ] && [ "$1" != -- ]; do
    export "$1"
    shift
done
shift
trap : INT # a Ctrl-C meant for the program must not end this script
stty -g >"$dir/$name.before"
sh -c 'echo $$ >"$0"; exec "$@"' "$dir/$name.pid" "$bin" "$@"
echo "EXITED $?"
stty -g >"$dir/$name.after"
if cmp -s "$dir/$name.before" "$dir/$name.after"; then
    echo "TERMINAL SAME"
else
    echo "TERMINAL CHANGED"
fi
exec sleep 300
EOF

start_in() {
    si_dir=$1 s_name=$2 s_cols=$3 s_rows=$4
    shift 4
    case " $* " in *" -- "*) ;; *) set -- "$@" -- ;; esac
    tm new-session -d -s "$s_name" -c "$si_dir" -x "$s_cols" -y "$s_rows" sh "$tmp/pane.sh" \
        "$tmp" "$SPRINGSIM" "$s_name" "LANG=$U8" "LC_ALL=$U8" TERM=xterm-256color \
        "XDG_CONFIG_HOME=$tmp/xdg" "$@"
    [ -n "$sockpath" ] || sockpath=$(tm display-message -p -t "$s_name" '#{socket_path}' 2>/dev/null)
}
start() { start_in "$PWD" "$@"; }
start_shell() {
    tm new-session -d -s "$1" -x "$2" -y "$3" env "PS1=PROMPT\$ " ENV=/dev/null sh -i
    [ -n "$sockpath" ] || sockpath=$(tm display-message -p -t "$1" '#{socket_path}' 2>/dev/null)
}

# ---- looking at the screen of session $S ----

# cap: the screen into $scr as a person sees it. capture-pane -p shows cells drawn in the
# terminal's line-drawing character set (smacs, as ncurses uses for boxes with
# TERM=xterm-256color) as the letters sent (q for ─, x for │); with -e it marks them with
# SO/SI, so they are taken from there and turned into the characters they show, and the
# colour escapes are dropped.
S=
scr=$tmp/screen
cap_s= cap_s1= cap_s2=
ACS_AWK='BEGIN {
    from = "jklmnqtuvwx`afg~yz{|}"
    split("┘ ┐ ┌ └ ┼ ─ ├ ┤ ┴ ┬ │ ◆ ▒ ° ± · ≤ ≥ π ≠ £", to, " ")
}
{
    gsub(/\033\[[0-9;:?]*[A-Za-z]/, "")
    gsub(/\033\][^\007\033]*(\007|\033\\)/, "")
    out = ""
    len = length($0)
    for (i = 1; i <= len; i++) {
        c = substr($0, i, 1)
        if (c == "\016") { acs = 1; continue }
        if (c == "\017") { acs = 0; continue }
        if (acs && c != " " && (k = index(from, c)) > 0) c = to[k]
        out = out c
    }
    sub(/ +$/, "", out)
    print out
}'
# The two captures before it are kept in $scr.1 and $scr.2 (for steady).
cap() {
    tm capture-pane -e -p -t "$S" 2>/dev/null | awk "$ACS_AWK" >"$scr.new"
    [ -f "$scr.1" ] && mv -f "$scr.1" "$scr.2"
    [ -f "$scr" ] && mv -f "$scr" "$scr.1"
    mv -f "$scr.new" "$scr"
    cap_s2=$cap_s1 cap_s1=$cap_s cap_s=$S
}
# cap_raw: the plain capture (for the check that no byte >= 0x80 reaches the terminal)
cap_raw() { tm capture-pane -p -t "$S" >"$scr" 2>/dev/null || : >"$scr"; }
has() { grep -qF -- "$1" "$scr"; }
has_re() { grep -qE -- "$1" "$scr"; }
lacks() { ! grep -qF -- "$1" "$scr"; }
keys() { tm send-keys -t "$S" "$@"; }
text() { tm send-keys -t "$S" -l "$1"; }
alive() { [ -s "$tmp/$1.pid" ] && kill -0 "$(cat "$tmp/$1.pid")" 2>/dev/null; }
# all_alive SESSION...: one check per session that its program is still running
all_alive() {
    for s in "$@"; do
        if alive "$s"; then pass; else
            S=$s
            cap
            fail "session $s: the program is no longer running; screen: $(brief "$scr" 'EXITED')"
        fi
    done
}
# the program has ended and pane.sh has said so: nothing on the screen will change
ended() { grep -qE '^TERMINAL (SAME|CHANGED)$' "$scr"; }

# poll SECONDS CMD [ARG...]: the one place that waits for the program. Captures the
# screen of $S every 0.1 s and runs CMD ARG... (which looks at $scr) until it succeeds;
# false after SECONDS, or as soon as the program has ended without CMD succeeding.
poll() {
    p_n=$(awk -v s="$1" 'BEGIN { print int(s * 10 + 0.5) }')
    shift
    while :; do
        cap
        "$@" && return 0
        ended && return 1
        [ "$p_n" -le 0 ] && return 1
        p_n=$((p_n - 1))
        sleep 0.1
    done
}
# steady: this capture of $S is the same as the two before it (0.1 s apart at least, in
# the same session): the frame on the screen is drawn whole. A terminal shows a frame as
# its bytes arrive, so a capture taken while they do shows the new frame's top over the
# old one's bottom (a status line twice, a title above the old view's axes).
steady() {
    [ "$cap_s2" = "$S" ] && [ "$cap_s1" = "$S" ] && cmp -s "$scr" "$scr.1" && cmp -s "$scr" "$scr.2"
}
# settle SECONDS CMD [ARG...]: poll until CMD holds on a steady screen. For a screen that
# does not move (paused, not the modes view's swinging shapes): what is asserted on it
# then is what a person sees, not a frame half sent. False after SECONDS, as poll.
settle() {
    st_n=$1
    shift
    poll "$st_n" steady_and "$@"
}
steady_and() { steady && "$@"; }
# wait_all SECONDS EXPR, settle_all SECONDS EXPR: the same for a shell expression (which
# looks at $scr), when what is asserted is several things on one screen: wait for them
# all together, not for one and then look for the others on a capture that may be older
# than the frame they are in.
holds() { eval "$1"; }
wait_all() { poll "$1" holds "$2"; }
settle_all() { settle "$1" holds "$2"; }
settle_for() { settle "${2:-5}" has "$1"; }
settle_re() { settle "${2:-5}" has_re "$1"; }
settle_gone() { settle "${2:-5}" lacks "$1"; }
wait_for() { poll "${2:-5}" has "$1"; }
wait_re() { poll "${2:-5}" has_re "$1"; }
wait_gone() { poll "${2:-5}" lacks "$1"; }
wait_same() { poll "${2:-5}" cmp -s "$1" "$scr"; }
# The t of the status line (first line), "" if none.
status_t() { sed -n '1s/.* t = \(-\{0,1\}[0-9][0-9.]*\) s.*/\1/p' "$scr"; }
t_at_least() { awk -v t="$(status_t)" -v m="$1" 'BEGIN { exit !(t != "" && t + 0 >= m) }'; }
wait_t() { poll "${2:-6}" t_at_least "$1"; } # wait_t T [SECONDS]: until t >= T
# the message line (the last non-blank line of the screen)
last_line() { awk 'NF { l = $0 } END { print l }' "$scr"; }
# the status line's history count
status_hist() { sed -n '1s/.*history \([0-9][0-9]*\).*/\1/p' "$scr"; }
# t plus K steps of DT (default 0.01), as the status line shows it with DT's digits
t_plus() {
    awk -v t="$1" -v k="$2" -v dt="${3:-0.01}" 'BEGIN {
        d = 2; s = dt ""; if (index(s, ".")) { d = length(s) - index(s, ".") } if (d < 2) d = 2
        printf "%.*f", d, t + k * dt }'
}
# paused, on a steady screen (a whole frame): echoes the t
t_settled() { has Paused && [ -n "$(status_t)" ] && steady; }
settled_t() {
    settle 5 t_settled
    status_t
}

# brief [FILE] [REGEX]: a few lines of a screen in one line, for failure messages: the
# first line, up to three lines matching REGEX, and the last non-blank line.
brief() {
    b_f=${1:-$scr}
    {
        sed -n 1p "$b_f"
        [ -n "$2" ] && grep -E -- "$2" "$b_f" | head -n 3
        awk 'NF { l = $0 } END { print l }' "$b_f"
    } | sed 's/  */ /g; s/^ //; s/ $//' | awk '{ printf "%s%s", (NR > 1 ? " | " : ""), $0 }' |
        cut -c 1-600
}
# first_diff EXPECTED ACTUAL: the first line where two screens differ, for messages.
first_diff() {
    awk 'NR == FNR { a[FNR] = $0; n = FNR; next }
         { b[FNR] = $0; m = FNR }
         END { for (i = 1; i <= (n > m ? n : m); i++) if (a[i] != b[i]) {
                   gsub(/  +/, " ", a[i]); gsub(/  +/, " ", b[i])
                   printf "line %d is \"%s\", expected \"%s\"", i, b[i], a[i]; exit } }' "$1" "$2"
}
# up NAME: S=NAME and true once the program shows its Controls panel; a failure otherwise
up() {
    S=$1
    wait_for Controls && return 0
    fail "$1: the program did not start; screen: $(brief)"
    return 1
}
# selected: the name of the selected control (the one marked ▸, or > in ASCII)
selected() { sed -n 's/.*[│x|][▸>]\([^ ]\( \{0,1\}[^ ]\)*\)  .*/\1/p' "$scr" | head -n 1; }
sel_is() { [ "$(selected)" = "$1" ]; }
sel_not() { [ "$(selected)" != "$1" ]; }
# select_control NAME: ↓ until the control NAME is selected (from one above it)
select_control() {
    sc_n=0
    cap
    while [ $sc_n -lt 20 ]; do
        sc_cur=$(selected)
        [ "$sc_cur" = "$1" ] && return 0
        keys Down
        poll 2 sel_not "$sc_cur" || return 1
        sc_n=$((sc_n + 1))
    done
    false
}

# ---- the plots on the screen ----
# CELLS_AWK: an awk prelude (mawk counts bytes) that splits the screen into cells: after
# it, c[ROW, COL] is the character at that cell (1-based), nrow the rows, ncol[ROW] the
# cells of a row. Programs append their own END block.
CELLS_AWK='BEGIN { for (i = 1; i < 256; i++) ord[sprintf("%c", i)] = i }
{
    nrow = NR; n = 0; len = length($0)
    for (i = 1; i <= len; i += w) {
        b = ord[substr($0, i, 1)]
        w = b >= 240 ? 4 : b >= 224 ? 3 : b >= 192 ? 2 : 1
        c[NR, ++n] = substr($0, i, w)
    }
    ncol[NR] = n
}
function cell(r, k) { return (r, k) in c ? c[r, k] : " " }
function braille(ch,   b2) { # a braille pattern with at least one dot (U+2801..U+28FF)
    if (length(ch) != 3 || ord[substr(ch, 1, 1)] != 226) return 0
    b2 = ord[substr(ch, 2, 1)]
    return b2 >= 160 && b2 <= 163 && ch != "\342\240\200"
}
# plot(TITLE): finds the frame whose top border holds TITLE and its axes: sets top,
# left, right (the frame), axc (the y axis column, that of the └ of the axes), axr (the
# x axis row) and axtop (the top row of the y axis); false if there is no such frame.
function plot(title,   r, k, s, t, m) {
    m = length(title)
    for (r = 1; r <= nrow; r++) {
        s = ""
        for (k = 1; k <= ncol[r]; k++) s = s c[r, k]
        if ((t = index(s, title)) == 0) continue
        # the cell of the title: count the cells of the bytes before it
        s = substr(s, 1, t - 1)
        for (k = 1; k <= ncol[r] && length(s) > 0; k++) s = substr(s, length(c[r, k]) + 1)
        for (left = k; left > 0 && cell(r, left) != "┌"; left--) ;
        for (right = k; right <= ncol[r] && cell(r, right) != "┐"; right++) ;
        if (left < 1 || right > ncol[r]) continue
        top = r
        axr = 0
        for (r = top + 1; r <= nrow && cell(r, left) != "└" && !axr; r++)
            for (k = left + 1; k < right; k++)
                if (cell(r, k) == "└") { axr = r; axc = k; break }
        if (!axr) return 0
        for (axtop = axr; axtop > top + 1 && (cell(axtop - 1, axc) == "│" || cell(axtop - 1, axc) == "┤"); axtop--) ;
        return axtop < axr
    }
    return 0
}
# at(R, T): the cell (column) where the text T begins on row R, 0 if it is not there
function at(r, t,   s, k, i) {
    s = ""
    for (k = 1; k <= ncol[r]; k++) s = s c[r, k]
    if ((i = index(s, t)) == 0) return 0
    s = substr(s, 1, i - 1)
    for (k = 1; k <= ncol[r] && length(s) > 0; k++) s = substr(s, length(c[r, k]) + 1)
    return k
}
function trim(s) { sub(/^ +/, "", s); sub(/ +$/, "", s); return s }
# label(R): the text left of the y axis on row R, trimmed
function label(r,   k, s) {
    s = ""
    for (k = left + 1; k < axc; k++) s = s cell(r, k)
    return trim(s)
}
'
# plot_awk PROGRAM [VAR=VALUE]...: runs CELLS_AWK and PROGRAM on $scr (or $PLOT_SCR)
plot_awk() { # plot_awk 'END { ... }' [VAR=VALUE]...
    pa_prog=$1
    shift
    LC_ALL=C awk "$@" "$CELLS_AWK$pa_prog" "${PLOT_SCR:-$scr}"
}
# cell_of TEXT [ROWTEXT]: "ROW COLUMN" (1-based cells) where TEXT first begins, on a row
# that also holds ROWTEXT if given; nothing if it is not on the screen
cell_of() {
    plot_awk 'END { for (r = 1; r <= nrow; r++) if ((k = at(r, text)) && (rowtext == "" || at(r, rowtext))) { print r, k; exit } }' \
        -v "text=$1" -v "rowtext=$2"
}
# plot_area TITLE: "COLS ROWS" of the drawing area of the plot titled TITLE (the cells
# right of its y axis, inside the frame, beside the y axis and above the x axis);
# nothing if there is none.
plot_area() {
    plot_awk 'END { if (plot(title)) print right - axc - 1, axr - axtop }' -v "title=$1"
}
# plot_peaks TITLE: the number of distinct peaks of the plot's trace: the highest dot of
# each column, read from left to right, rising at least two rows from a trough and then
# falling at least two rows counts once.
plot_peaks() {
    plot_awk 'END {
        if (!plot(title)) { print 0; exit }
        peaks = 0; rising = 0; lo = ""; hi = ""
        for (k = axc + 1; k < right; k++) {
            h = ""
            for (r = axtop; r < axr; r++) if (braille(c[r, k])) { h = axr - r; break }
            if (h == "") continue
            if (lo == "" || h < lo) lo = h
            if (!rising && h >= lo + 2) { rising = 1; hi = h }
            if (rising && h > hi) hi = h
            if (rising && h <= hi - 2) { peaks++; rising = 0; lo = h }
        }
        print peaks }' -v "title=$1"
}
# plot_dots TITLE: the number of cells of the plot's drawing area with braille dots
plot_dots() {
    plot_awk 'END {
        n = 0
        if (plot(title)) for (r = axtop; r < axr; r++) for (k = axc + 1; k < right; k++)
            if (braille(c[r, k])) n++
        print n }' -v "title=$1"
}
# plot_ticks TITLE: what is wrong with the y axis of the plot titled TITLE, nothing if all
# is well: every label left of the axis is a whole number ("-0.5", "400", "-2e4"), the
# labels fall evenly from top to bottom (equal steps, or equal ratios for powers of ten,
# so none is cut), and the gridline rows (┤ on the axis) are evenly spaced.
plot_ticks() {
    plot_awk 'END {
        if (!plot(title)) { print "no plot titled " title; exit }
        nl = 0; ng = 0; bad = ""
        for (r = axtop; r < axr; r++) {
            if (cell(r, axc) == "┤") g[++ng] = r
            else if (cell(r, axc) != "│") bad = bad " row " r " has \"" cell(r, axc) "\" on the axis;"
            s = label(r)
            if (s == "") continue
            v[++nl] = s
            if (s !~ /^-?[0-9]+(\.[0-9]+)?(e-?[0-9]+)?$/) bad = bad " label \"" s "\" is not a number;"
        }
        if (ng < 2) bad = bad " " ng " gridlines;"
        for (i = 3; i <= ng; i++) if (g[i] - g[i - 1] != g[2] - g[1])
            { bad = bad " gridline rows " g[1] "," g[2] "," g[3] (ng > 3 ? "," g[4] : "") "... not evenly spaced;"; break }
        if (nl < 2) bad = bad " " nl " labels;"
        else {
            # a log axis (every label a power of ten such as 1e-2) falls evenly in log
            lg = 1
            for (i = 1; i <= nl; i++) if (v[i] !~ /^1e-?[0-9]+$/) lg = 0
            if (lg) for (i = 1; i <= nl; i++) v[i] = log(v[i]) / log(10)
            step = v[1] - v[2]
            for (i = 2; i <= nl; i++) {
                d = v[i - 1] - v[i]
                if (d <= 0 || d - step > step * 0.1 || step - d > step * 0.1)
                    { bad = bad " labels " v[i - 1] ", " v[i] " do not fall evenly (first step " step ");"; break }
            }
        }
        if (bad != "") { printf "%s:", title; l = ""; for (i = 1; i <= nl; i++) l = l " " v[i]; print bad " labels" l }
    }' -v "title=$1"
}
