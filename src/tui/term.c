/* term.c: curses set-up and restore, the palettes, and the signal handlers that give
 * the terminal back on every way out. */
#include "term.h"

#include <term.h>

#include <langinfo.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static volatile sig_atomic_t quit_signal; /* SIGINT, SIGTERM, SIGHUP received */
static bool curses_on;
static bool utf8;
static bool color;
static bool rich; /* 256 colours */

bool term_utf8(void)
{
    return utf8;
}

int term_quit_signal(void)
{
    return quit_signal;
}

void term_stop(void)
{
    if (curses_on) {
        curses_on = false;
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

static void on_quit_signal(int sig)
{
    quit_signal = sig;
}

/* A crash: give the terminal back, then die of the same signal. */
static void on_fatal_signal(int sig)
{
    term_stop();
    signal(sig, SIG_DFL);
    raise(sig);
}

static void install_signals(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_quit_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    sigaction(SIGHUP, &sa, NULL);
    sa.sa_handler = on_fatal_signal;
    sa.sa_flags = SA_RESETHAND;
    sigaction(SIGSEGV, &sa, NULL);
    sigaction(SIGBUS, &sa, NULL);
    sigaction(SIGFPE, &sa, NULL);
    sigaction(SIGILL, &sa, NULL);
    sigaction(SIGABRT, &sa, NULL);
}

/* Palettes chosen to read on black and on white: mid-tone hues only, no yellow, white,
 * black or light grey for anything that carries information. 256 colours: blue, green,
 * orange, red, purple, teal, ochre, magenta, brown, slate. 8 colours have no mid tones:
 * the hues that read on both backgrounds come first, yellow and cyan last. */
static void init_colors(void)
{
    const char *no_color = getenv("NO_COLOR");
    color = has_colors() && !(no_color && *no_color);
    if (!color)
        return;
    start_color();
    use_default_colors();
    static const short c256[10] = {27, 28, 166, 160, 128, 30, 136, 163, 94, 61};
    static const short c8[10] = {COLOR_BLUE, COLOR_GREEN,  COLOR_RED,   COLOR_MAGENTA,
                                 COLOR_CYAN, COLOR_YELLOW, COLOR_BLUE,  COLOR_GREEN,
                                 COLOR_RED,  COLOR_MAGENTA};
    rich = COLORS >= 256;
    for (int i = 0; i < 10; i++)
        init_pair((short)(PAIR_MASS + i), rich ? c256[i] : c8[i], -1);
    init_pair(PAIR_MOTOR, rich ? 163 : COLOR_MAGENTA, -1);
    init_pair(PAIR_SPRING, rich ? 28 : COLOR_GREEN, -1);
    init_pair(PAIR_GRID, rich ? 245 : -1, -1);
    init_pair(PAIR_TITLE, rich ? 32 : -1, -1);
    init_pair(PAIR_WARN, rich ? 160 : COLOR_RED, -1);
    init_pair(PAIR_WALL, -1, -1);
    init_pair(PAIR_SELECT, -1, -1);
}

static attr_t eight_color_boost(int p);

attr_t term_attr(int p)
{
    attr_t a = (color ? COLOR_PAIR(p) : A_NORMAL) | eight_color_boost(p);
    switch (p) {
    case PAIR_TITLE:
    case PAIR_WARN:
        return a | A_BOLD;
    case PAIR_SELECT:
        return a | A_REVERSE;
    default:
        return a;
    }
}

attr_t term_mass_attr(int i)
{
    return term_attr(PAIR_MASS + i % 10);
}

/* With 8 colours, blue is too dark to read on black: its bright form reads on both. */
static attr_t eight_color_boost(int p)
{
    return color && !rich && p >= PAIR_MASS && p < PAIR_MASS + 10 && (p - PAIR_MASS) % 6 == 0
               ? A_BOLD
               : 0;
}

bool term_start(void)
{
    utf8 = strcmp(nl_langinfo(CODESET), "UTF-8") == 0;
    if (!isatty(STDIN_FILENO) || !isatty(STDOUT_FILENO)) {
        fprintf(stderr, "springsim: the interactive program needs a terminal; use --headless, "
                        "--modes or --sweep for scripts\n");
        return false;
    }
    if (!newterm(NULL, stdout, stdin)) {
        fprintf(stderr, "springsim: cannot use this terminal (TERM=%s)\n",
                getenv("TERM") ? getenv("TERM") : "unset");
        return false;
    }
    /* A terminal that cannot place the cursor (TERM=dumb) would show one garbled line. */
    const char *cup = tigetstr("cup");
    if (cup == NULL || cup == (char *)-1) {
        endwin();
        fprintf(stderr, "springsim: this terminal (TERM=%s) cannot move the cursor; the "
                        "interactive program needs one (use --headless, --modes or --sweep)\n",
                getenv("TERM") ? getenv("TERM") : "unset");
        return false;
    }
    curses_on = true;
    atexit(term_stop);
    install_signals();
    cbreak();
    noecho();
    nonl();
    keypad(stdscr, TRUE);
    curs_set(0);
    set_escdelay(25);
    mousemask(BUTTON1_PRESSED | BUTTON1_RELEASED | BUTTON4_PRESSED | REPORT_MOUSE_POSITION
#ifdef BUTTON5_PRESSED
                  | BUTTON5_PRESSED
#endif
              ,
              NULL);
    mouseinterval(0);
    init_colors();
    return true;
}
