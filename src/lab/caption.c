/* caption.c: lesson text made into caption lines (caption.h). */
#include "caption.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <unistr.h>
#include <uniwidth.h>

#include "../core/config.h"
#include "../app/spell.h"

void caption_text(const char *text, bool utf8, char *out, size_t len)
{
    char esc[4 * 4096 + 8];
    config_escape(text, strlen(text), 4096, esc, sizeof esc);
    if (utf8) {
        snprintf(out, len, "%s", esc);
        return;
    }
    size_t o = 0;
    for (const char *s = esc; *s && o + 8 < len;) {
        size_t n;
        const char *spelt = (unsigned char)*s >= 0x80 ? spell_ascii(s, &n) : NULL;
        if ((unsigned char)*s < 0x80) {
            out[o++] = *s++;
        } else if (spelt) {
            o += (size_t)snprintf(out + o, len - o, "%s", spelt);
            s += n;
        } else {
            out[o++] = '?';
            for (s++; ((unsigned char)*s & 0xc0) == 0x80; s++)
                ;
        }
    }
    if (len)
        out[o < len ? o : len - 1] = '\0';
}

/* The length of the escape at s that caption_text's escaping writes for a control or
 * format character (\n, \xNN, \uXXXX, \UXXXXXXXX), or 0. */
static size_t escape_length(const char *s)
{
    if (s[0] != '\\' || !s[1])
        return 0;
    if (strchr("abtnvfr", s[1]))
        return 2;
    size_t digits = s[1] == 'x' ? 2 : s[1] == 'u' ? 4 : s[1] == 'U' ? 8 : 0;
    for (size_t i = 0; i < digits; i++)
        if (!strchr("0123456789abcdef", s[2 + i]) || !s[2 + i])
            return 0;
    return digits ? digits + 2 : 0;
}

int caption_glyph(const char *s, size_t *len)
{
    size_t escape = escape_length(s);
    if (escape) { /* shown as written, one column a byte, never cut */
        *len = escape;
        return (int)escape;
    }
    if ((unsigned char)*s < 0x80) {
        *len = 1;
        return 1;
    }
    ucs4_t uc;
    size_t room = strnlen(s, 4);
    int n = u8_mbtouc(&uc, (const uint8_t *)s, room);
    *len = n > 0 ? (size_t)n : 1;
    int w = uc_width(uc, "UTF-8");
    return w < 0 ? 1 : w;
}

int caption_width(const char *text)
{
    int cols = 0;
    for (size_t k; *text; text += k)
        cols += caption_glyph(text, &k);
    return cols;
}

/* The plain wrap: lines of at most cols columns cut at blanks. */
static int wrap(const char *text, int cols, char (*lines)[CAPTION_LINE], int n, int max)
{
    const char *s = text;
    while (*s && n < max) {
        if (*s == '\n' || *s == ' ') {
            s++;
            continue;
        }
        size_t len = 0, fit = 0, k;
        int used = 0;
        while (s[len] && s[len] != '\n') {
            int w = caption_glyph(s + len, &k);
            if (used + w > cols || len + k >= CAPTION_LINE)
                break;
            if (s[len] == ' ')
                fit = len;
            used += w;
            len += k;
        }
        bool more = s[len] && s[len] != '\n';
        if (more && s[len] == ' ')
            fit = len;
        if (more && fit > 0)
            len = fit;
        if (len == 0) /* a character wider than the panel: shown alone */
            caption_glyph(s, &len);
        /* Combining marks stay with the character they follow. */
        while (s[len] && caption_glyph(s + len, &k) == 0 && len + k < CAPTION_LINE)
            len += k;
        snprintf(lines[n++], CAPTION_LINE, "%.*s", (int)len, s);
        s += len;
    }
    return n;
}

int caption_wrap(const char *text, int cols, char (*lines)[CAPTION_LINE], int n, int max)
{
    if (cols < 1)
        cols = 1;
    int end = wrap(text, cols, lines, n, max);
    if (end - n < 2 || end >= max || strchr(lines[end - 1], ' '))
        return end;
    /* A last line of one word: narrower lines that take no more of them keep it company. */
    for (int c = cols - 1; c >= cols * 3 / 4 && c > 0; c--)
        if (wrap(text, c, lines, n, max) == end && strchr(lines[end - 1], ' '))
            return end;
    return wrap(text, cols, lines, n, max);
}
