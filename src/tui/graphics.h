/* graphics.h: the charts' drawing areas as images in terminals that show them: the
 * terminal asked once at start (before curses) what it can do (primary device attributes:
 * 4 is sixel; kitty's graphics query), its cell size in pixels (TIOCGWINSZ, CSI 16 t, CSI
 * 14 t), its background and foreground (OSC 11, 10), the palette entries the colour
 * pairs use (OSC 4: the images are drawn in the colours the text is shown in, or carry
 * the legend's marks where it does not say) and sixel's colour registers (XTSMGRAPHICS);
 * each chart's image sent at its drawing area's cell
 * only when its content changed, never over an overlay, again after a resize, Ctrl+L or
 * an overlay closing. Braille otherwise: inside tmux or screen, with low bandwidth, in a
 * terminal that does not answer. */
#ifndef SPRINGSIM_GRAPHICS_H
#define SPRINGSIM_GRAPHICS_H

#include <stdbool.h>
#include <stdint.h>

#include "../app/answer.h"
#include "../core/config.h"
#include "../fig/lib.h"
#include "../fig/pixels.h"
#include "chart.h"

struct answers;
#define GRAPHICS_TIMEOUT_MS 100 /* how long the terminal has to answer at start */
#define GRAPHICS_LATE_S 5.0      /* answers later than that, but within this, still count */
#define GRAPHICS_SLOTS 12       /* images shown at once, at most (the modes view's ten) */
/* The images' pace: a batch of P pixels and B bytes is followed by none for P / PIXELS_S or
 * B / BYTES_S seconds, the longer (so a large terminal refreshes its images less often,
 * as the braille plots do, and the link and the CPU are spared). */
#define GRAPHICS_PIXELS_S 1.2e6
#define GRAPHICS_SIXEL_BYTES_S 280e3
#define GRAPHICS_KITTY_BYTES_S 300e3

enum graphics_mode { GRAPHICS_BRAILLE, GRAPHICS_SIXEL, GRAPHICS_KITTY };

struct graphics {
    enum graphics_mode mode;   /* what the charts are drawn with now */
    enum graphics_mode can;    /* what the terminal said it shows (BRAILLE: no images) */
    bool tty;                  /* standard input and output are a terminal */
    bool multiplexed;          /* inside tmux or screen */
    bool asked;                /* the terminal has answered, or had its time to (asked at
                                * start, or when pixels were first wanted) */
    bool waiting;              /* the queries are out, their answers not all in */
    double wait_until;         /* monotonic seconds: then the answers are taken as they are */
    struct answers *got;       /* what they said so far, while waiting (and while late) */
    double late_until;         /* monotonic seconds: the wait ended without DA1's answer;
                                * answers that come until then are still taken */
    bool late_taken;           /* answers that came late were just taken (graphics_settle) */
    bool sized;                /* its cell size in pixels is known */
    enum config_graphics want; /* what graphics_follow last followed (-1: nothing yet) */
    bool low;                  /* ... and the low refresh then */
    int cw, ch;                /* a cell in pixels (0: not known) */
    int registers;             /* sixel's colour registers, as the terminal said (XTSMGRAPHICS;
                                * 0: not said) */
    bool dark;                 /* the background is dark */
    double bg[3];              /* the background (0..1) */
    bool fg_known;             /* the terminal said its foreground (OSC 10) */
    double fg[3];              /* and it is this */
    bool pal_known[256];       /* the palette entries it said (OSC 4) */
    double pal[256][3];        /* and their colours */
    bool overlay;              /* an overlay was open at the last frame */
    int n;                     /* images on the screen */
    struct rect at[GRAPHICS_SLOTS];  /* where */
    uint64_t hash[GRAPHICS_SLOTS];   /* of what */
    struct fig_bytes img, out, rgb; /* the image, the bytes sent, the pixels on their way */
    const struct fig_lib *lib; /* the figure library, once pixels were chosen */
    char said[160];            /* why the charts are braille though pixels were asked for
                                * ("braille inside tmux or screen"), or "" */
    double next_at;            /* monotonic seconds before which no image is sent */
    struct answer_scan answers; /* the terminal's answers told from keys: every byte read
                                * goes through it (keys typed while the queries were
                                * out wait there) */
};

/* Chooses the mode for c's graphics and low bandwidth, after curses started: braille
 * without asking where they choose it, and inside tmux and screen; otherwise the
 * terminal is asked and the charts are braille until it answered (graphics_settle). */
void graphics_detect(struct graphics *g, const struct config *c);

/* Follows the Graphics control (want) and the low refresh (low) where they changed since
 * the last call: braille, or pixels where the terminal shows them (asking it first if
 * pixels were never wanted before: braille until graphics_settle); leaving pixels clears
 * the images, and the screen is drawn again. True when it changed something; g->said then
 * says why it is braille if pixels were asked for by name. */
bool graphics_follow(struct graphics *g, enum config_graphics want, bool low);

/* An answer the loop's key scanner completed (NUL-ended): taken while the queries' answers
 * are awaited, and for GRAPHICS_LATE_S after the wait if DA1's had not come. */
void graphics_heard(struct graphics *g, const char *answer);

/* Whether answers are still due (the wait, or its late time): the key scanner then holds
 * a lone Esc a moment (answer.h). */
bool graphics_awaiting(const struct graphics *g);

/* Once the terminal has answered every query (DA1's answer is the last), or had
 * GRAPHICS_TIMEOUT_MS to: takes what it said and chooses the mode again as the last
 * graphics_follow asked. True when it did (g->said as graphics_follow leaves it). A
 * terminal whose DA1 answer comes later (a slow link), within GRAPHICS_LATE_S: its
 * answers are taken then and the mode chosen again (g->late_taken set). */
bool graphics_settle(struct graphics *g);

/* The mode in force as --graphics spells it (CONFIG_GRAPHICS_SIXEL, _KITTY, _BRAILLE). */
enum config_graphics graphics_now(const struct graphics *g);

/* The images on the screen are gone (resize, Ctrl+L, a new layout): send them again. */
void graphics_invalidate(struct graphics *g);

/* True when an image could go now (always, for braille): the plots refresh no faster
 * than their images can follow, so no refresh is computed for nothing. */
bool graphics_ready(const struct graphics *g);

/* After a frame: the n charts shown as images where they changed; with overlay, none
 * (kitty's are taken away, since text does not cover them). */
void graphics_frame(struct graphics *g, struct chart *const *charts, int n, bool overlay);

/* Frees what it holds. */
void graphics_free(struct graphics *g);

/* The name of a mode, as --graphics spells it. */
const char *graphics_name(enum graphics_mode mode);

#endif
