/* term.c: curses set-up and restore, the palettes, and the signal handlers that give
 * the terminal back on every way out. */
#include "term.h"

#include <term.h>

#include <fcntl.h>
#include <langinfo.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <termios.h>
#include <unistd.h>

/* Seconds a quit signal leaves for the loop to end and endwin() to finish before the
 * terminal is taken back by force: output blocked by a stalled link or Ctrl-S would
 * otherwise hold the program inside curses' write loop (it retries on EINTR) for ever. */
#define QUIT_GRACE 1

static volatile sig_atomic_t quit_signal; /* the first terminating signal received */
static struct termios shell_modes;        /* the terminal's modes before curses */
static bool have_shell_modes;
static char restore_seq[256]; /* what endwin() sends, for the forced way out */
static size_t restore_len;
static bool curses_on;
static bool utf8;   /* UTF-8 glyphs: the locale has them and --glyphs is not ascii */
static bool blocks; /* block characters in place of braille (--glyphs blocks) */
static bool color;
static bool rich; /* 256 colours */
static bool cursor_stays; /* the terminal cannot hide its cursor (vt100) */

bool term_utf8(void)
{
    return utf8;
}

bool term_blocks(void)
{
    return blocks;
}

int term_quit_signal(void)
{
    return quit_signal;
}

/* Bracketed paste on (xterm's mode 2004: pasted text comes between CSI 200 ~ and CSI
 * 201 ~, app/answer.h), where the terminal reports the mouse as xterm does. */
static bool paste_mode;

void term_stop(void)
{
    if (curses_on) {
        curses_on = false;
        if (paste_mode) {
            fputs("\033[?2004l", stdout);
            fflush(stdout);
        }
        endwin();
    }
}

void term_die_of_signal(void)
{
    if (quit_signal) {
        signal(quit_signal, SIG_DFL);
        raise(quit_signal);
    }
}

bool term_check_hangup(void)
{
    struct pollfd p[2] = {{STDIN_FILENO, POLLIN, 0}, {STDOUT_FILENO, POLLOUT, 0}};
    if (poll(p, 2, 0) < 0)
        return false;
    for (int i = 0; i < 2; i++)
        if (p[i].revents & (POLLHUP | POLLERR | POLLNVAL)) {
            if (!quit_signal)
                quit_signal = SIGHUP;
            return true;
        }
    return false;
}

/* Appends terminfo capability cap (if the terminal has it) to restore_seq. */
static void restore_add(const char *cap)
{
    const char *s = tigetstr(cap);
    if (s == NULL || s == (char *)-1)
        return;
    size_t n = strlen(s);
    if (restore_len + n < sizeof restore_seq) {
        memcpy(restore_seq + restore_len, s, n);
        restore_len += n;
    }
}

/* The bytes endwin() would send, gathered while curses is up: CAN first (it ends an
 * escape sequence a discarded frame may have left half sent), mouse reporting and
 * bracketed paste off where the terminal reports the mouse as xterm does (kmous \E[M or
 * \E[<), then the attributes, cursor, keypad and screen as they were. */
static void restore_prepare(void)
{
    static const char can[] = "\030";
    static const char mouse_off[] = "\033[?1006l\033[?1003l\033[?1002l\033[?1000l"
                                    "\033[?2004l";
    memcpy(restore_seq, can, sizeof can - 1);
    restore_len = sizeof can - 1;
    const char *kmous = tigetstr("kmous");
    paste_mode = kmous != NULL && kmous != (char *)-1 && strncmp(kmous, "\033[", 2) == 0;
    if (paste_mode) {
        memcpy(restore_seq + restore_len, mouse_off, sizeof mouse_off - 1);
        restore_len += sizeof mouse_off - 1;
    }
    restore_add("sgr0");
    restore_add("cnorm");
    restore_add("rmkx");
    restore_add("rmcup");
}

/* ncurses 6.4 sends what it has at every cursor move until the program has once left
 * curses and come back (after newterm its screen counts as not yet started: a flush
 * meant for low-level terminfo programs), so a frame went out in a dozen writes, each
 * waking the terminal. Leaving and coming back once, before anything is drawn, makes a
 * frame one write; the terminal sees the alternate screen left and entered again at
 * once, with nothing on it yet. */
static void leave_and_return(void)
{
    endwin();
    doupdate();
}

/* The way out when a quit signal finds output blocked: only async-signal-safe calls.
 * Frames the terminal has not read are dropped and output stopped by Ctrl-S restarted
 * (turning IXON off does that: Linux's n_tty_set_termios; TCOON undoes only TCOOFF), so
 * the restoring bytes can be queued without waiting. They are written non-blocking: what
 * does not fit is lost, the program must not wait for the terminal. The modes are set
 * back at once; then the program dies of the signal, as a shell expects. */
static void force_exit(int sig)
{
    int fd = STDOUT_FILENO;
    int flags = fcntl(fd, F_GETFL);
    tcflush(fd, TCOFLUSH);
    struct termios flowing;
    if (tcgetattr(fd, &flowing) == 0 && (flowing.c_iflag & IXON)) {
        flowing.c_iflag &= ~(tcflag_t)IXON;
        tcsetattr(fd, TCSANOW, &flowing);
    }
    if (flags != -1 && fcntl(fd, F_SETFL, flags | O_NONBLOCK) == 0) {
        ssize_t sent = write(fd, restore_seq, restore_len); /* if not, the screen is lost */
        (void)sent;
        fcntl(fd, F_SETFL, flags); /* the file is shared with the shell */
    }
    if (have_shell_modes)
        tcsetattr(fd, TCSANOW, &shell_modes);
    signal(sig, SIG_DFL);
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, sig);
    sigprocmask(SIG_UNBLOCK, &set, NULL);
    raise(sig);
    _exit(128 + sig);
}

/* SIGINT, SIGTERM, SIGHUP, SIGQUIT and every other signal that ends a program (except
 * where the program was started with it ignored, as `trap '' HUP` does: it stays
 * ignored): the loop ends and gives the terminal back; if it has not within QUIT_GRACE
 * seconds, or a second such signal comes, the terminal is taken back by force. */
static void on_quit_signal(int sig)
{
    if (quit_signal)
        force_exit(quit_signal);
    quit_signal = sig;
    alarm(QUIT_GRACE);
}

/* The grace period is over (or SIGALRM came from outside: then it is a quit signal). */
static void on_alarm(int sig)
{
    if (quit_signal)
        force_exit(quit_signal);
    on_quit_signal(sig);
}

/* A crash: give the terminal back, then die of the same signal. */
static void on_fatal_signal(int sig)
{
    term_stop();
    signal(sig, SIG_DFL);
    raise(sig);
}

/* Ctrl+Z: bracketed paste off while the shell has the terminal, on again once the
 * program is back; curses' own handler (tstp_curses) gives the screen back between. */
static void (*tstp_curses)(int);

static void on_suspend(int sig)
{
    static const char off[] = "\033[?2004l", on[] = "\033[?2004h";
    ssize_t sent = write(STDOUT_FILENO, off, sizeof off - 1);
    if (tstp_curses) {
        tstp_curses(sig);
    } else {
        signal(sig, SIG_DFL);
        raise(sig);
        signal(sig, on_suspend);
    }
    sent = write(STDOUT_FILENO, on, sizeof on - 1);
    (void)sent;
}

/* Installed after curses, which has put its own SIGTSTP handler in place (or not). */
static void install_suspend(void)
{
    struct sigaction sa, old;
    if (!paste_mode || sigaction(SIGTSTP, NULL, &old) != 0 || old.sa_handler == SIG_IGN ||
        (old.sa_flags & SA_SIGINFO))
        return;
    tstp_curses = old.sa_handler == SIG_DFL ? NULL : old.sa_handler;
    memset(&sa, 0, sizeof sa);
    sigemptyset(&sa.sa_mask);
    sa.sa_handler = on_suspend;
    sigaction(SIGTSTP, &sa, NULL);
}

static void install_signals(void)
{
    static const int quit[] = {SIGINT,  SIGTERM,   SIGHUP,  SIGQUIT, SIGPIPE,
                               SIGUSR1, SIGUSR2,   SIGXCPU, SIGXFSZ, SIGVTALRM,
                               SIGPROF,
#ifdef SIGPWR
                               SIGPWR,
#endif
#ifdef SIGSTKFLT
                               SIGSTKFLT,
#endif
    };
    static const int fatal[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTRAP, SIGSYS};
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sigemptyset(&sa.sa_mask);
    sa.sa_handler = on_quit_signal;
    for (size_t i = 0; i < sizeof quit / sizeof quit[0]; i++) {
        struct sigaction old;
        if (sigaction(quit[i], NULL, &old) == 0 && old.sa_handler != SIG_IGN)
            sigaction(quit[i], &sa, NULL);
    }
    sa.sa_handler = on_alarm; /* the grace timer: caught even where it was ignored */
    sigaction(SIGALRM, &sa, NULL);
    sa.sa_handler = on_fatal_signal;
    sa.sa_flags = SA_RESETHAND;
    for (size_t i = 0; i < sizeof fatal / sizeof fatal[0]; i++)
        sigaction(fatal[i], &sa, NULL);
}

/* Palettes chosen to read on black and on white: mid-tone hues only, no yellow, white,
 * black or light grey for anything that carries information. 256 colours: blue, green,
 * orange, red, purple, teal, ochre, magenta, brown, slate. 8 colours have no mid tones
 * and yellow does not read on white: five hues (blue, green, red, magenta, cyan), again
 * for masses 6 to 10 (told apart by their digit at the curve's end, plots.c), always bold
 * (a terminal such as xterm shows them bright then, and the legends are bold: one colour
 * a mass, in the legend, the curve and the chain). The motor is the terminal's own
 * foreground, in bold, so that it is no mass's colour in either. */
static const short c256[10] = {27, 28, 166, 160, 128, 30, 136, 163, 94, 61};
static const short c8[10] = {COLOR_BLUE, COLOR_GREEN, COLOR_RED, COLOR_MAGENTA, COLOR_CYAN,
                             COLOR_BLUE, COLOR_GREEN, COLOR_RED, COLOR_MAGENTA, COLOR_CYAN};
static short shown_as[PAIR_COUNT]; /* the colour each pair's text shows in (-1: foreground) */
static int shown_rgb[PAIR_COUNT];  /* direct colour: the pair's 0xRRGGBB (-1: none) */
static bool direct;                /* the terminal takes colours as 0xRRGGBB (xterm-direct) */

/* xterm's 256-colour entry idx (16..255) as 0xRRGGBB: the 6x6x6 cube, the greys. */
static int cube_rgb(int idx)
{
    static const int level[6] = {0, 95, 135, 175, 215, 255};
    if (idx >= 232)
        return (8 + 10 * (idx - 232)) * 0x010101;
    idx -= 16;
    return level[idx / 36] << 16 | level[idx / 6 % 6] << 8 | level[idx % 6];
}

/* Pair p in foreground fg (a 256-colour entry, or -1), as the terminal takes it: with
 * direct colour, that entry's red, green and blue themselves, so every terminal shows
 * the same colours. */
static void pair_256(short p, short fg)
{
    shown_as[p] = fg;
    if (direct && fg >= 16) {
        shown_rgb[p] = cube_rgb(fg);
        init_extended_pair(p, shown_rgb[p], -1);
    } else {
        init_pair(p, fg, -1);
    }
}

static void init_colors(enum config_color want)
{
    const char *no_color = getenv("NO_COLOR");
    bool refused = want == CONFIG_COLOR_NEVER ||
                   (want == CONFIG_COLOR_AUTO && no_color && *no_color);
    color = has_colors() && !refused;
    for (int p = 0; p < PAIR_COUNT; p++)
        shown_as[p] = -1, shown_rgb[p] = -1;
    if (!color)
        return;
    start_color();
    use_default_colors();
    rich = COLORS >= 256;
    direct = COLORS > 256 && tigetflag("RGB") > 0;
    if (rich) {
        for (int i = 0; i < 10; i++)
            pair_256((short)(PAIR_MASS + i), c256[i]);
        pair_256(PAIR_SPRING, 28);
        pair_256(PAIR_GRID, 245);
        pair_256(PAIR_TITLE, 32);
        pair_256(PAIR_WARN, 160);
    } else {
        for (int i = 0; i < 10; i++) {
            init_pair((short)(PAIR_MASS + i), c8[i], -1);
            shown_as[PAIR_MASS + i] = (short)(c8[i] + 8); /* bold: bright */
        }
        init_pair(PAIR_SPRING, COLOR_GREEN, -1);
        init_pair(PAIR_GRID, -1, -1);
        init_pair(PAIR_TITLE, -1, -1);
        init_pair(PAIR_WARN, COLOR_RED, -1);
        shown_as[PAIR_SPRING] = COLOR_GREEN;
        shown_as[PAIR_WARN] = COLOR_RED + 8;
    }
    init_pair(PAIR_MOTOR, -1, -1);
    init_pair(PAIR_WALL, -1, -1);
    init_pair(PAIR_SELECT, -1, -1);
}

int term_pair_color(int p)
{
    return p > 0 && p < PAIR_COUNT ? shown_as[p] : -1;
}

int term_pair_rgb(int p)
{
    return p > 0 && p < PAIR_COUNT ? shown_rgb[p] : -1;
}

int term_color_candidates(int *idx, int max)
{
    static const short more[] = {28, 245, 32, 160, COLOR_GREEN, COLOR_RED + 8};
    int n = 0;
    for (int i = 0; i < 5 && n < max; i++)
        idx[n++] = c8[i] + 8;
    for (int i = 0; i < 10 && n < max; i++)
        idx[n++] = c256[i];
    for (size_t i = 0; i < sizeof more / sizeof more[0] && n < max; i++)
        idx[n++] = more[i];
    return n;
}

static attr_t eight_color_boost(int p);

attr_t term_attr(int p)
{
    attr_t a = (color ? COLOR_PAIR(p) : A_NORMAL) | eight_color_boost(p);
    switch (p) {
    case PAIR_TITLE:
    case PAIR_WARN:
    case PAIR_MOTOR:
        return a | A_BOLD;
    case PAIR_SELECT:
        return a | A_REVERSE;
    default:
        return a;
    }
}

void term_park_cursor(void)
{
    if (cursor_stays)
        move(0, 0); /* the status line's first cell, blank */
}

int term_hues(void)
{
    return !color ? 0 : rich ? 10 : 5;
}

attr_t term_mass_attr(int i)
{
    return term_attr(PAIR_MASS + i % 10);
}

/* With 8 colours the masses are bold: blue is too dark to read on black, its bright form
 * reads on both, and every mass is shown the one way (the legends are bold). */
static attr_t eight_color_boost(int p)
{
    return color && !rich && p >= PAIR_MASS && p < PAIR_MASS + 10 ? A_BOLD : 0;
}

/* 1 when the terminal on standard output can place the cursor, 0 when it cannot, -1
 * when there is no description of it. */
static int cursor_addressable(void)
{
    int err;
    if (setupterm(NULL, STDOUT_FILENO, &err) != OK)
        return -1;
    const char *cup = tigetstr("cup");
    bool addressable = cup != NULL && cup != (char *)-1;
    del_curterm(cur_term);
    return addressable;
}

bool term_dumb(void)
{
    const char *term = getenv("TERM");
    if (term && strcmp(term, "dumb") == 0)
        return true;
    return isatty(STDIN_FILENO) && isatty(STDOUT_FILENO) && cursor_addressable() == 0;
}

bool term_start(enum config_color want_color, enum config_glyphs glyphs)
{
    /* The one place the characters are chosen: every drawing asks term_utf8() and
     * term_blocks(). */
    utf8 = strcmp(nl_langinfo(CODESET), "UTF-8") == 0 && glyphs != CONFIG_GLYPHS_ASCII;
    blocks = utf8 && glyphs == CONFIG_GLYPHS_BLOCKS;
    if (!isatty(STDIN_FILENO) || !isatty(STDOUT_FILENO)) {
        fprintf(stderr, "springsim: the interactive program needs a terminal; use --plain, "
                        "--headless, --modes or --sweep for scripts\n");
        return false;
    }
    /* The terminal's description is looked at before curses starts: newterm() would leak
     * its screen when there is none, and curses has nothing to do on a terminal that
     * cannot place the cursor (TERM=dumb would show one garbled line). */
    const char *term = getenv("TERM") ? getenv("TERM") : "unset";
    int addressable = cursor_addressable();
    if (addressable < 0) {
        fprintf(stderr, "springsim: cannot use this terminal (TERM=%s; --plain works on "
                        "any terminal)\n", term);
        return false;
    }
    if (!addressable) {
        fprintf(stderr, "springsim: this terminal (TERM=%s) cannot move the cursor; the "
                        "interactive program needs one (--plain works on any terminal)\n",
                term);
        return false;
    }
    have_shell_modes = tcgetattr(STDOUT_FILENO, &shell_modes) == 0;
    if (!newterm(NULL, stdout, stdin)) {
        fprintf(stderr, "springsim: cannot use this terminal (TERM=%s; --plain works on "
                        "any terminal)\n", term);
        return false;
    }
    curses_on = true;
    leave_and_return();
    atexit(term_stop);
    restore_prepare();
    install_signals();
    cbreak();
    noecho();
    nonl();
    keypad(stdscr, TRUE);
    cursor_stays = curs_set(0) == ERR;
    set_escdelay(25);
    mousemask(BUTTON1_PRESSED | BUTTON1_RELEASED | BUTTON4_PRESSED | REPORT_MOUSE_POSITION
#ifdef BUTTON5_PRESSED
                  | BUTTON5_PRESSED
#endif
              ,
              NULL);
    mouseinterval(0);
    if (paste_mode) {
        fputs("\033[?2004h", stdout);
        fflush(stdout);
    }
    install_suspend();
    init_colors(want_color);
    return true;
}
