/* graphics.c: the terminal's answers at start, and the images after each frame. The
 * queries go out together, primary device attributes last: every terminal answers that
 * one, and answers in order, so its answer ends the wait; a terminal that answers nothing
 * costs GRAPHICS_TIMEOUT_MS once, and gets braille. */
#include "graphics.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <time.h>
#include <unistd.h>

#include <curses.h>

#include "../fig/lib.h"
#include "term.h"

#define KITTY_CHUNK 4096 /* base64 bytes a kitty escape carries, at most */
#define KITTY_ID 1811    /* our images' numbers: KITTY_ID + slot */

static const char queries[] = "\033_Gi=31,s=1,v=1,a=q,t=d,f=24;AAAA\033\\" /* kitty */
                              "\033[16t"                                   /* cell size */
                              "\033[14t"                                   /* text area */
                              "\033]11;?\033\\"                            /* background */
                              "\033]10;?\033\\"                            /* foreground */
                              "%s"                      /* OSC 4: the palette's colours used */
                              "\033[?1;1;0S"      /* XTSMGRAPHICS: sixel's colour registers */
                              "\033[c";                                    /* DA1 */

const char *graphics_name(enum graphics_mode mode)
{
    return mode == GRAPHICS_SIXEL ? "sixel" : mode == GRAPHICS_KITTY ? "kitty" : "braille";
}

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

/* What the answers say. */
struct answers {
    bool da1, sixel, kitty;
    int cell_w, cell_h;  /* CSI 16 t */
    int area_w, area_h;  /* CSI 14 t */
    bool bg;
    double rgb[3];
    int registers;       /* XTSMGRAPHICS: sixel's colour registers (0: not said) */
    bool fg_known;       /* OSC 10: the foreground */
    double fg[3];
    bool pal_known[256]; /* OSC 4: palette entries */
    double pal[256][3];
};

/* The numbers of a CSI answer "ESC [ ? a ; b ; ... F" at p (F its final byte). */
static int csi_numbers(const char *p, int *v, int max, char *final)
{
    int n = 0;
    p += 2;
    if (*p == '?')
        p++;
    while (n < max) {
        if (!isdigit((unsigned char)*p))
            break;
        long x = strtol(p, (char **)&p, 10);
        v[n++] = x > 1000000 ? 1000000 : (int)x; /* a number past any screen's */
        if (*p != ';')
            break;
        p++;
    }
    *final = *p;
    return n;
}

/* One hexadecimal component of "rgb:RRRR/GGGG/BBBB" (1 to 4 digits) as 0..1. */
static double hex_part(const char **p)
{
    char *end;
    unsigned long v = strtoul(*p, &end, 16);
    int digits = (int)(end - *p);
    *p = *end == '/' ? end + 1 : end;
    return digits > 0 && digits <= 4 ? v / (double)((1UL << (4 * digits)) - 1) : 0.0;
}

static void parse(const char *buf, struct answers *a)
{
    for (const char *p = buf; (p = strchr(p, '\033')); p++) {
        int v[16], n;
        char final;
        if (p[1] == '[') {
            n = csi_numbers(p, v, 16, &final);
            if (final == 'c' && p[2] == '?') {
                a->da1 = true;
                for (int i = 1; i < n; i++)
                    a->sixel |= v[i] == 4;
            } else if (final == 't' && n == 3 && v[0] == 6) {
                a->cell_h = v[1], a->cell_w = v[2];
            } else if (final == 't' && n == 3 && v[0] == 4) {
                a->area_h = v[1], a->area_w = v[2];
            } else if (final == 'S' && p[2] == '?' && n == 3 && v[0] == 1 && v[1] == 0) {
                a->registers = v[2];
            }
        } else if (p[1] == '_' && p[2] == 'G') {
            const char *semi = strchr(p, ';');
            a->kitty |= semi && strncmp(semi + 1, "OK", 2) == 0;
        } else if (p[1] == ']' && strncmp(p + 2, "11;rgb:", 7) == 0) {
            const char *q = p + 9;
            for (int i = 0; i < 3; i++)
                a->rgb[i] = hex_part(&q);
            a->bg = true;
        } else if (p[1] == ']' && strncmp(p + 2, "10;rgb:", 7) == 0) {
            const char *q = p + 9;
            for (int i = 0; i < 3; i++)
                a->fg[i] = hex_part(&q);
            a->fg_known = true;
        } else if (p[1] == ']' && p[2] == '4' && p[3] == ';') {
            char *q;
            long idx = strtol(p + 4, &q, 10);
            if (q > p + 4 && idx >= 0 && idx < 256 && strncmp(q, ";rgb:", 5) == 0) {
                const char *h = q + 5;
                for (int i = 0; i < 3; i++)
                    a->pal[idx][i] = hex_part(&h);
                a->pal_known[idx] = true;
            }
        }
    }
}

/* Sends the queries; their answers come in through the loop's keys (graphics_heard) and
 * are taken as they are once DA1's has come or the wait is over (graphics_settle): the
 * screen is drawn in braille meanwhile, so a terminal that answers nothing does not delay
 * the first frame. Keys typed meanwhile wait in g->answers (answer.h): nothing is
 * flushed. */
static void ask(struct graphics *g)
{
    /* The palette entries any pair may use, one OSC 4 asking for them all. */
    int idx[32], n = term_color_candidates(idx, 32);
    char pal[400] = "\033]4", out[sizeof queries + sizeof pal];
    size_t at = strlen(pal);
    for (int i = 0; i < n && at + 8 < sizeof pal; i++)
        at += (size_t)snprintf(pal + at, sizeof pal - at, ";%d;?", idx[i]);
    snprintf(pal + at, sizeof pal - at, "\033\\");
    int len = snprintf(out, sizeof out, queries, pal);
    free(g->got);
    g->got = calloc(1, sizeof *g->got);
    g->waiting = g->got != NULL;
    g->wait_until = now_ms() / 1e3 + GRAPHICS_TIMEOUT_MS / 1e3;
    g->late_until = 0.0;
    fflush(stdout); /* what curses wrote goes first */
    if (g->got && (len <= 0 || write(STDOUT_FILENO, out, (size_t)len) != (ssize_t)len))
        g->wait_until = 0.0; /* nothing will answer */
}

bool graphics_awaiting(const struct graphics *g)
{
    return g->got && (g->waiting || now_ms() / 1e3 < g->late_until);
}

void graphics_heard(struct graphics *g, const char *answer)
{
    if (graphics_awaiting(g))
        parse(answer, g->got);
}

/* Inside tmux or screen (no passthrough asked for): braille. */
static bool multiplexed(void)
{
    const char *term = getenv("TERM");
    return getenv("TMUX") || getenv("STY") ||
           (term && (strncmp(term, "screen", 6) == 0 || strncmp(term, "tmux", 4) == 0));
}

/* Takes what the terminal answered (a: nothing where it said nothing): what it shows, its
 * cell size and its colours. */
static void heard(struct graphics *g, const struct answers *ans)
{
    struct answers a = ans ? *ans : (struct answers){0};
    g->asked = true;
    struct winsize ws;
    g->cw = g->ch = 0;
    if (ioctl(STDOUT_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_xpixel && ws.ws_ypixel && ws.ws_col &&
        ws.ws_row)
        g->cw = ws.ws_xpixel / ws.ws_col, g->ch = ws.ws_ypixel / ws.ws_row;
    else if (a.cell_w > 0 && a.cell_h > 0)
        g->cw = a.cell_w, g->ch = a.cell_h;
    else if (a.area_w > 0 && a.area_h > 0 && ioctl(STDOUT_FILENO, TIOCGWINSZ, &ws) == 0 &&
             ws.ws_col && ws.ws_row)
        g->cw = a.area_w / ws.ws_col, g->ch = a.area_h / ws.ws_row;
    if (a.bg) {
        memcpy(g->bg, a.rgb, sizeof g->bg);
        g->dark = 0.2126 * a.rgb[0] + 0.7152 * a.rgb[1] + 0.0722 * a.rgb[2] < 0.5;
    }
    g->registers = a.registers;
    g->fg_known = a.fg_known;
    memcpy(g->fg, a.fg, sizeof g->fg);
    memcpy(g->pal_known, a.pal_known, sizeof g->pal_known);
    memcpy(g->pal, a.pal, sizeof g->pal);
    /* However large the terminal says its cells are: images are scaled down to
     * fig_pixels_fit's caps. */
    g->sized = g->cw >= 2 && g->ch >= 4;
    g->can = !g->sized ? GRAPHICS_BRAILLE
             : a.kitty ? GRAPHICS_KITTY
             : a.sixel ? GRAPHICS_SIXEL
                       : GRAPHICS_BRAILLE;
}

void graphics_detect(struct graphics *g, const struct config *c)
{
    memset(g, 0, sizeof *g);
    g->mode = g->can = GRAPHICS_BRAILLE;
    chart_use_pixels(false); /* and no strokes kept for images */
    g->bg[0] = g->bg[1] = g->bg[2] = 1.0;
    g->want = (enum config_graphics)-1;
    g->tty = isatty(STDIN_FILENO) && isatty(STDOUT_FILENO);
    g->multiplexed = multiplexed();
    graphics_follow(g, c->graphics, c->low_bandwidth);
}

/* Switches to mode: kitty's images deleted when leaving kitty; the screen drawn again,
 * which clears sixel's (and the braille under a new image). */
static void set_mode(struct graphics *g, enum graphics_mode mode)
{
    if (mode == g->mode)
        return;
    if (g->mode == GRAPHICS_KITTY) {
        fputs("\033_Ga=d,d=a,q=2\033\\", stdout);
        fflush(stdout); /* now, not when the program ends */
    }
    g->mode = mode;
    chart_use_pixels(mode != GRAPHICS_BRAILLE);
    graphics_invalidate(g);
    if (curscr)
        clearok(curscr, TRUE);
}

/* The mode for g->want and g->low as far as the terminal has said, asking it first if it
 * never was; braille while its answers are awaited. */
static void choose(struct graphics *g)
{
    enum config_graphics want = g->want;
    g->said[0] = '\0';
    enum graphics_mode named = want == CONFIG_GRAPHICS_SIXEL   ? GRAPHICS_SIXEL
                               : want == CONFIG_GRAPHICS_KITTY ? GRAPHICS_KITTY
                                                               : GRAPHICS_BRAILLE;
    enum graphics_mode mode = GRAPHICS_BRAILLE;
    if (want == CONFIG_GRAPHICS_BRAILLE || !g->tty) {
        mode = GRAPHICS_BRAILLE;
    } else if (g->low) {
        snprintf(g->said, sizeof g->said, "braille while the refresh is low (the Refresh "
                 "control)");
    } else if (g->multiplexed) {
        snprintf(g->said, sizeof g->said, "braille inside tmux or screen");
    } else if (!g->asked) {
        if (!g->waiting)
            ask(g); /* braille until the answers are in: graphics_settle */
    } else if (named != GRAPHICS_BRAILLE && g->sized) {
        mode = named; /* asked for by name: believed where the cell size is known */
    } else if (named != GRAPHICS_BRAILLE) {
        snprintf(g->said, sizeof g->said, "the terminal did not say its cell size in "
                 "pixels; braille");
    } else {
        mode = g->can;
    }
    if (want == CONFIG_GRAPHICS_AUTO)
        g->said[0] = '\0'; /* auto takes what there is, and the control shows it */
    char why[sizeof g->said - 10];
    if (mode != GRAPHICS_BRAILLE && !(g->lib = fig_lib(why, sizeof why))) {
        mode = GRAPHICS_BRAILLE; /* said even for auto: the install is broken */
        snprintf(g->said, sizeof g->said, "braille: %s", why);
    }
    set_mode(g, mode);
}

bool graphics_follow(struct graphics *g, enum config_graphics want, bool low)
{
    if (want == g->want && low == g->low)
        return false;
    g->want = want, g->low = low;
    choose(g);
    return true;
}

bool graphics_settle(struct graphics *g)
{
    g->late_taken = false;
    if (!g->got)
        return false;
    double now = now_ms() / 1e3;
    bool late = !g->waiting; /* the wait ended without DA1's answer */
    if (late && now >= g->late_until) {
        free(g->got); /* nothing more is coming */
        g->got = NULL;
        return false;
    }
    if (!g->got->da1 && (late || now < g->wait_until))
        return false;
    g->late_taken = late; /* what a slow link brought after the wait */
    g->waiting = false;
    heard(g, g->got);
    if (g->got->da1) {
        free(g->got);
        g->got = NULL;
    } else {
        g->late_until = g->wait_until + GRAPHICS_LATE_S; /* its answers may be on the way */
    }
    choose(g);
    return true;
}

enum config_graphics graphics_now(const struct graphics *g)
{
    return g->mode == GRAPHICS_SIXEL   ? CONFIG_GRAPHICS_SIXEL
           : g->mode == GRAPHICS_KITTY ? CONFIG_GRAPHICS_KITTY
                                       : CONFIG_GRAPHICS_BRAILLE;
}

void graphics_invalidate(struct graphics *g)
{
    g->n = 0;
    /* The images on their way are no longer the screen's: the new ones go at once, not
     * after the old batch's pacing (with huge cells an enlarged plot waited 10 s). */
    g->next_at = 0.0;
}

/* xterm's default colour idx (0..255): its 16, the 6x6x6 cube, the greys. */
static void xterm_rgb(int idx, double rgb[3])
{
    static const unsigned char sixteen[16][3] = {
        {0, 0, 0},       {205, 0, 0},   {0, 205, 0},   {205, 205, 0},
        {0, 0, 238},     {205, 0, 205}, {0, 205, 205}, {229, 229, 229},
        {127, 127, 127}, {255, 0, 0},   {0, 255, 0},   {255, 255, 0},
        {92, 92, 255},   {255, 0, 255}, {0, 255, 255}, {255, 255, 255}};
    static const unsigned char level[6] = {0, 95, 135, 175, 215, 255};
    for (int i = 0; i < 3; i++) {
        int c = idx < 16    ? sixteen[idx][i]
                : idx < 232 ? level[(idx - 16) / (i == 0 ? 36 : i == 1 ? 6 : 1) % 6]
                            : 8 + 10 * (idx - 232);
        rgb[i] = c / 255.0;
    }
}

/* The colours the terminal shows each pair's text in, for the images: the palette's
 * entries and the foreground as it said them, else xterm's and black or white; *known
 * tells whether it said every one used (the gridlines keep their faint grey). */
static void pair_colors(const struct graphics *g, struct fig_palette *pal, bool *known)
{
    fig_palette_default(pal, g->dark);
    *known = true;
    for (int p = 1; p < PAIR_COUNT && p < FIG_COLOR_COUNT; p++) {
        int idx = term_pair_color(p), rgb = term_pair_rgb(p);
        if (p == PAIR_GRID || p == PAIR_SELECT) {
            continue;
        } else if (rgb >= 0) { /* direct colour: what it was given */
            for (int i = 0; i < 3; i++)
                pal->rgb[p][i] = (rgb >> (16 - 8 * i) & 255) / 255.0;
        } else if (idx < 0 && g->fg_known) {
            memcpy(pal->rgb[p], g->fg, sizeof g->fg);
        } else if (idx < 0) {
            fig_rgb(FIG_MOTOR, g->dark, pal->rgb[p]); /* white on dark, black on light */
            *known = false;
        } else if (g->pal_known[idx]) {
            memcpy(pal->rgb[p], g->pal[idx], sizeof g->pal[idx]);
        } else {
            xterm_rgb(idx, pal->rgb[p]);
            *known = false;
        }
    }
}

/* FNV-1a of more bytes. */
static uint64_t mix(uint64_t h, const void *p, size_t n)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < n; i++)
        h = (h ^ b[i]) * 0x100000001b3ULL;
    return h;
}

/* What the image of c depends on. */
static uint64_t chart_hash(const struct fig_chart *c)
{
    uint64_t h = c->strokes ? strokes_hash(c->strokes) : 0xcbf29ce484222325ULL;
    h = mix(h, &c->ax, 4 * sizeof c->ax);
    h = mix(h, &c->xt, sizeof c->xt);
    h = mix(h, c->legend, sizeof c->legend); /* drawn in the image where the palette is not
                                              * known */
    h = mix(h, c->legend_color, sizeof c->legend_color);
    return mix(h, &c->yt, sizeof c->yt);
}

static void out_add(struct fig_bytes *b, const void *p, size_t n)
{
    if (b->len + n > b->cap) {
        size_t cap = b->cap ? b->cap : 65536;
        while (cap < b->len + n)
            cap *= 2;
        unsigned char *d = realloc(b->data, cap);
        if (!d) {
            b->failed = true;
            return;
        }
        b->data = d, b->cap = cap;
    }
    memcpy(b->data + b->len, p, n);
    b->len += n;
}

/* n bytes as base64 (RFC 4648, padded) into out; its length. */
static size_t base64(const unsigned char *in, size_t n, char *out)
{
    static const char digit[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    size_t o = 0;
    for (size_t i = 0; i < n; i += 3) {
        unsigned long v = (unsigned long)in[i] << 16 | (i + 1 < n ? in[i + 1] << 8 : 0) |
                          (i + 2 < n ? in[i + 2] : 0);
        out[o++] = digit[v >> 18 & 63];
        out[o++] = digit[v >> 12 & 63];
        out[o++] = i + 1 < n ? digit[v >> 6 & 63] : '=';
        out[o++] = i + 2 < n ? digit[v & 63] : '=';
    }
    return o;
}

/* The PNG in g->img as kitty escapes, placed at the cursor over cols x rows cells
 * (kitty scales it there: an image drawn with smaller cells than the terminal's still
 * fills its area), numbered id. Every chunk but the last carries a multiple of 3 bytes,
 * so each is base64 on its own. */
static void kitty_escapes(struct graphics *g, int id, int cols, int rows)
{
    char head[96], chunk[KITTY_CHUNK + 8];
    size_t per = KITTY_CHUNK / 4 * 3; /* raw bytes a chunk carries */
    for (size_t at = 0; at < g->img.len; at += per) {
        size_t n = g->img.len - at < per ? g->img.len - at : per;
        size_t len = base64(g->img.data + at, n, chunk);
        int hl = at == 0 ? snprintf(head, sizeof head,
                                    "\033_Ga=T,f=100,i=%d,q=2,C=1,z=-1,c=%d,r=%d,m=%d;", id,
                                    cols, rows, at + n < g->img.len)
                         : snprintf(head, sizeof head, "\033_Gm=%d;", at + n < g->img.len);
        out_add(&g->out, head, (size_t)hl);
        out_add(&g->out, chunk, len);
        out_add(&g->out, "\033\\", 2);
    }
}

bool graphics_ready(const struct graphics *g)
{
    return g->mode == GRAPHICS_BRAILLE || now_ms() / 1e3 >= g->next_at;
}

void graphics_frame(struct graphics *g, struct chart *const *charts, int n, bool overlay)
{
    if (g->mode == GRAPHICS_BRAILLE)
        return;
    if (overlay || g->overlay) {
        /* Kitty's images are not covered by text: they go while an overlay is open. */
        if (overlay && !g->overlay && g->mode == GRAPHICS_KITTY)
            fputs("\033_Ga=d,d=a,q=2\033\\", stdout);
        if (!overlay)
            graphics_invalidate(g); /* it closed: what it covered comes back */
        g->overlay = overlay;
        if (overlay) {
            fflush(stdout);
            return;
        }
    }
    double now = now_ms() / 1e3;
    if (now < g->next_at)
        return; /* what changed goes at a later frame */
    g->out.len = 0;
    g->out.failed = false;
    out_add(&g->out, "\0337", 2); /* the cursor, as curses left it */
    /* Sixel at the cursor, not at the screen's top left (DECSDM off: xterm's
     * sixelScrolling, which a user may have turned the other way). */
    if (g->mode == GRAPHICS_SIXEL)
        out_add(&g->out, "\033[?80l", 6);
    int sent = 0;
    double pixels = 0.0;
    struct fig_palette pal;
    bool known;
    pair_colors(g, &pal, &known);
    for (int i = 0; i < n && i < GRAPHICS_SLOTS; i++) {
        struct fig_chart pic;
        chart_picture(charts[i], &pic);
        if (!pic.axes || pic.aw < 1 || pic.ah < 1)
            continue;
        uint64_t h = chart_hash(&pic);
        struct rect r = charts[i]->area;
        if (i < g->n && g->hash[i] == h && memcmp(&g->at[i], &r, sizeof r) == 0)
            continue;
        enum fig_encoding e = g->mode == GRAPHICS_KITTY ? FIG_KITTY_PNG : FIG_SIXEL;
        int cw = g->cw, ch = g->ch;
        g->lib->pixels_fit(pic.aw, pic.ah, &cw, &ch);
        if (g->lib->pixels(&pic, cw, ch, &pal, g->bg, !known, e, g->registers, &g->img,
                           &g->rgb) != 0)
            continue;
        char pos[32];
        int pl = snprintf(pos, sizeof pos, "\033[%d;%dH", r.y + 1, r.x + 1);
        out_add(&g->out, pos, (size_t)pl);
        if (g->mode == GRAPHICS_KITTY)
            kitty_escapes(g, KITTY_ID + i, pic.aw, pic.ah);
        else
            out_add(&g->out, g->img.data, g->img.len);
        g->hash[i] = h, g->at[i] = r;
        pixels += (double)pic.aw * pic.ah * cw * ch;
        sent++;
    }
    g->n = n < GRAPHICS_SLOTS ? n : GRAPHICS_SLOTS;
    out_add(&g->out, "\0338", 2);
    if (!sent || g->out.failed)
        return;
    double rate = g->mode == GRAPHICS_KITTY ? GRAPHICS_KITTY_BYTES_S : GRAPHICS_SIXEL_BYTES_S;
    g->next_at = now + fmax(pixels / GRAPHICS_PIXELS_S, (double)g->out.len / rate);
    fflush(stdout);
    size_t done = 0;
    while (done < g->out.len) {
        ssize_t w = write(STDOUT_FILENO, g->out.data + done, g->out.len - done);
        if (w <= 0)
            break;
        done += (size_t)w;
    }
}

void graphics_free(struct graphics *g)
{
    free(g->got);
    g->got = NULL;
    if (g->lib) { /* nothing is kept before pixels are drawn, nor without the library */
        g->lib->bytes_free(&g->img);
        g->lib->bytes_free(&g->out);
        g->lib->bytes_free(&g->rgb);
    }
}
