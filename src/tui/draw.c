/* draw.c: the drawing primitives every part of the screen uses. */
#include "draw.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "../lab/caption.h"
#include "../app/spell.h"
#include "term.h"

chtype draw_line(enum line l)
{
    if (!term_utf8())
        return (chtype)"-|+++++++"[l];
    switch (l) {
    case L_H:
        return ACS_HLINE;
    case L_V:
        return ACS_VLINE;
    case L_UL:
        return ACS_ULCORNER;
    case L_UR:
        return ACS_URCORNER;
    case L_LL:
        return ACS_LLCORNER;
    case L_LR:
        return ACS_LRCORNER;
    case L_RTEE:
        return ACS_RTEE;
    case L_TTEE:
        return ACS_TTEE;
    case L_PLUS:
        return ACS_PLUS;
    }
    return '+';
}

int draw_width(const char *s)
{
    /* Without UTF-8 the text is drawn spelled in ASCII (draw_text): "m/s²" takes 5. */
    bool spell = !term_utf8();
    int n = 0;
    while (*s) {
        size_t len;
        const char *spelt;
        if (spell && (unsigned char)*s >= 0x80 && (spelt = spell_ascii(s, &len)) != NULL) {
            n += (int)strlen(spelt);
            s += len;
            continue;
        }
        if (spell) { /* one column a character, spelled '?' */
            n += (*s & 0xC0) != 0x80;
            s++;
            continue;
        }
        /* Screen columns: a CJK character two, a combining mark none. */
        size_t k;
        n += caption_glyph(s, &k);
        s += k;
    }
    return n;
}

/* s spelled in ASCII into out. */
static const char *ascii(const char *s, char *out, size_t len)
{
    size_t o = 0;
    while (*s && o + 6 < len) {
        if ((unsigned char)*s < 0x80) {
            out[o++] = *s++;
            continue;
        }
        size_t n;
        const char *spelt = spell_ascii(s, &n);
        if (spelt) {
            for (const char *a = spelt; *a; a++)
                out[o++] = *a;
            s += n;
        } else {
            out[o++] = '?';
            s++;
            while ((*s & 0xC0) == 0x80)
                s++;
        }
    }
    out[o] = '\0';
    return out;
}

int draw_text(int y, int x, int w, const char *s)
{
    char plain[1024];
    if (w <= 0 || y < 0 || x < 0)
        return 0;
    if (!term_utf8())
        s = ascii(s, plain, sizeof plain);
    int cols = 0, lastw = 1;
    const char *p = s, *last = s; /* last: where the last character that fits starts */
    while (*p) {
        size_t k = 1;
        int cw = term_utf8() ? caption_glyph(p, &k) : 1; /* a CJK character takes two */
        const char *q = p + k;
        if (cols + cw > w)
            break;
        if (cw > 0)
            last = p, lastw = cw;
        cols += cw;
        p = q;
    }
    /* Text that does not fit ends in "…" (ASCII "..."), never cut silently; trailing
     * blanks cut are no loss. */
    const char *rest = p;
    while (*rest == ' ')
        rest++;
    if (*rest && cols > 0) {
        if (term_utf8()) {
            mvaddnstr(y, x, s, (int)(last - s));
            mvaddstr(y, x + cols - lastw, "…");
            cols += 1 - lastw;
        } else { /* ASCII: one byte a column */
            int dots = cols < 3 ? cols : 3;
            mvaddnstr(y, x, s, cols - dots);
            mvaddnstr(y, x + cols - dots, "...", dots);
        }
        return cols;
    }
    mvaddnstr(y, x, s, (int)(p - s));
    return cols;
}

int draw_printf(int y, int x, int w, const char *fmt, ...)
{
    char buf[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    return draw_text(y, x, w, buf);
}

int draw_text_attr(int y, int x, int w, attr_t a, const char *s)
{
    attron(a);
    int n = draw_text(y, x, w, s);
    attroff(a);
    return n;
}

void draw_frame(struct rect r, const char *title, bool centre)
{
    if (r.h < 2 || r.w < 2)
        return;
    mvaddch(r.y, r.x, draw_line(L_UL));
    mvhline(r.y, r.x + 1, draw_line(L_H), r.w - 2);
    mvaddch(r.y, r.x + r.w - 1, draw_line(L_UR));
    mvvline(r.y + 1, r.x, draw_line(L_V), r.h - 2);
    mvvline(r.y + 1, r.x + r.w - 1, draw_line(L_V), r.h - 2);
    mvaddch(r.y + r.h - 1, r.x, draw_line(L_LL));
    mvhline(r.y + r.h - 1, r.x + 1, draw_line(L_H), r.w - 2);
    mvaddch(r.y + r.h - 1, r.x + r.w - 1, draw_line(L_LR));
    if (!title || r.w < 6)
        return;
    int shown = draw_width(title);
    if (shown > r.w - 4)
        shown = r.w - 4;
    int x = centre ? r.x + (r.w - shown - 2) / 2 : r.x + 1;
    attron(term_attr(PAIR_TITLE));
    mvaddch(r.y, x, ' ');
    draw_text(r.y, x + 1, shown, title);
    addch(' ');
    attroff(term_attr(PAIR_TITLE));
}

void draw_clear(struct rect r)
{
    for (int y = r.y; y < r.y + r.h; y++)
        mvhline(y, r.x, ' ', r.w);
}

void draw_canvas(const struct canvas *c, int y, int x)
{
    if (!c)
        return;
    bool utf8 = term_utf8(), blocks = term_blocks();
    for (int cy = 0; cy < c->rows; cy++) {
        for (int cx = 0; cx < c->cols; cx++) {
            uint8_t bits = canvas_bits(c, cx, cy);
            if (!bits)
                continue;
            attr_t a = term_attr(c->color[(size_t)cy * c->cols + cx]);
            if (utf8) {
                /* The wide character itself: no multibyte decoding per cell. */
                wchar_t wc[2] = {(wchar_t)(blocks ? braille_quadrant(bits) : 0x2800u + bits), 0};
                cchar_t cc;
                setcchar(&cc, wc, a & ~A_COLOR, (short)PAIR_NUMBER(a), NULL);
                mvadd_wch(y + cy, x + cx, &cc);
            } else {
                mvaddch(y + cy, x + cx, (chtype)braille_ascii(bits) | a);
            }
        }
    }
}
