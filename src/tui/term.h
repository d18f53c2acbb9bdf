/* term.h: the terminal itself: set-up and restore, colours, signals, and the one fatal
 * path. Every other tui file draws through what this sets up. */
#ifndef SPRINGSIM_TERM_H
#define SPRINGSIM_TERM_H

#include <stdbool.h>

#include <curses.h>

#include "../core/config.h"

/* Colour pairs. Information is never drawn in a grey or with A_DIM alone: every pair
 * reads on dark and light backgrounds, with 8 or 256 colours. */
enum pair {
    PAIR_MASS = 1, /* masses 1..10: PAIR_MASS + i */
    PAIR_MOTOR = 11,
    PAIR_SPRING,
    PAIR_GRID, /* gridlines only: the one thing that may be faint */
    PAIR_TITLE,
    PAIR_WARN,
    PAIR_WALL,
    PAIR_SELECT,
    PAIR_COUNT
};

/* True for a terminal that cannot place the cursor (TERM=dumb, or a description without
 * one): the plain mode serves it instead of curses. */
bool term_dumb(void);

/* Starts curses on the terminal with colour as want_color says (auto: unless NO_COLOR
 * is set and not empty) and the glyphs asked for; false (with the reason on stderr) when
 * it cannot. */
bool term_start(enum config_color want_color, enum config_glyphs glyphs);

/* Gives the terminal back (safe to call twice, and from atexit). */
void term_stop(void);

/* True where the locale is UTF-8 and --glyphs is not ascii: braille, box drawing and
 * symbols allowed. */
bool term_utf8(void);

/* How many masses the colours tell apart: 10 with 256 colours, 5 with 8, 0 without
 * colour. Past that, the plots mark each curve's end with its mass's digit. */
int term_hues(void);

/* Where the terminal cannot hide its cursor (vt100), puts it on the status line's
 * first cell, a blank, rather than where drawing ended; before each refresh. */
void term_park_cursor(void);

/* True where canvases draw in quadrant blocks instead of braille (--glyphs blocks in a
 * UTF-8 locale). */
bool term_blocks(void);

/* Attribute for colour pair p, or its mono stand-in. */
attr_t term_attr(int p);

/* The terminal colour (0..255) pair p's text shows in, bold included (8 colours: a
 * mass's bright form), or -1 for the terminal's foreground (no colour, or the pair's). */
int term_pair_color(int p);

/* With direct colour (TERM=xterm-direct), the 0xRRGGBB pair p's text shows in, which
 * the terminal takes as it is; -1 otherwise. */
int term_pair_rgb(int p);

/* Every colour some pair may show in, with 8 colours or 256, into idx (max at most);
 * returns how many: the ones to ask the terminal for before curses knows which. */
int term_color_candidates(int *idx, int max);

/* Attribute for mass i's colour. */
attr_t term_mass_attr(int i);

/* True when the terminal has gone (hung up, closed): SIGHUP is then taken as received,
 * whether or not it came. Cheap enough to call whenever getch() gives ERR. */
bool term_check_hangup(void);

/* The terminating signal received (SIGINT, SIGTERM, SIGHUP, SIGQUIT, ...), or 0. A second
 * one, or the loop not ending within a second of the first (output blocked), ends the
 * program at once, the terminal given back as far as it will take it. */
int term_quit_signal(void);

/* After term_stop: dies of the quit signal received, so a shell sees 128 + signal. */
void term_die_of_signal(void);

#endif
