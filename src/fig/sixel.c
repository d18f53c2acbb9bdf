/* sixel.c: an image as sixel on xterm's 256 colours, encoded here in one pass over the
 * pixels. libsixel did this before at about 120 ns a pixel (for every image: all 256
 * colour definitions, a quantiser's lookup per pixel, its allocations); this takes a few.
 * Each pixel takes the nearest of the 256 colours (squared distance in RGB, the first of
 * equals, as libsixel's lookup does), so a colour drawn from the palette is the colour
 * sent; a register is defined where its colour is first used, and only then. Bands of six
 * rows; in each, one line per colour present, from its first column to its last, runs of
 * four or more repeated (DEC's sixel format as VT330/VT340 and xterm read it). */
#include "sixel.h"

#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define CACHE 4096 /* pixel colours remembered (open addressing; the images hold few) */

/* xterm's 256 colours as libsixel's built-in palette has them: its first 16 in steps of
 * 0, 128, 192, 255; the 6x6x6 cube; 24 greys. */
static void palette(unsigned char rgb[256][3])
{
    static const unsigned char sixteen[16][3] = {
        {0, 0, 0},       {128, 0, 0},   {0, 128, 0},   {128, 128, 0},
        {0, 0, 128},     {128, 0, 128}, {0, 128, 128}, {192, 192, 192},
        {128, 128, 128}, {255, 0, 0},   {0, 255, 0},   {255, 255, 0},
        {0, 0, 255},     {255, 0, 255}, {0, 255, 255}, {255, 255, 255}};
    static const unsigned char level[6] = {0, 95, 135, 175, 215, 255};
    for (int i = 0; i < 256; i++)
        for (int k = 0; k < 3; k++)
            rgb[i][k] = i < 16    ? sixteen[i][k]
                        : i < 232 ? level[(i - 16) / (k == 0 ? 36 : k == 1 ? 6 : 1) % 6]
                                  : (unsigned char)(8 + 10 * (i - 232));
}

/* The encoder's working state. */
struct enc {
    unsigned char pal[256][3];
    uint32_t key[CACHE];  /* pixel colour + 1 (0: empty) */
    unsigned char val[CACHE];
    short slot[256];      /* a colour's line in the band (-1: not in it) */
    unsigned char used[256]; /* colours in the band, in order of first use */
    int nused;
    int lo[256], hi[256]; /* each line's first and last column */
    bool defined[256];    /* its register was defined */
    unsigned char *rows;  /* 256 lines of w sixels (bits), zero between bands */
    char *out;            /* the sequence */
    size_t len, cap;
    bool failed;
};

static void put(struct enc *e, const char *p, size_t n)
{
    if (e->len + n > e->cap) {
        size_t cap = e->cap ? e->cap : 65536;
        while (cap < e->len + n)
            cap *= 2;
        char *d = e->failed ? NULL : realloc(e->out, cap);
        if (!d) {
            e->failed = true;
            return;
        }
        e->out = d, e->cap = cap;
    }
    memcpy(e->out + e->len, p, n);
    e->len += n;
}

/* A decimal number after the character c. */
static void put_num(struct enc *e, char c, int v)
{
    char b[16];
    int n = (int)sizeof b;
    do {
        b[--n] = (char)('0' + v % 10);
        v /= 10;
    } while (v > 0);
    b[--n] = c;
    put(e, b + n, sizeof b - (size_t)n);
}

/* The nearest palette colour to 0xRRGGBB. */
static unsigned char nearest(struct enc *e, uint32_t px)
{
    uint32_t h = (px * 2654435761u) >> 20 & (CACHE - 1);
    while (e->key[h] && e->key[h] != px + 1)
        h = (h + 1) & (CACHE - 1);
    if (e->key[h])
        return e->val[h];
    int r = px >> 16 & 255, g = px >> 8 & 255, b = px & 255, best = 0;
    long least = -1;
    for (int i = 0; i < 256; i++) {
        long dr = r - e->pal[i][0], dg = g - e->pal[i][1], db = b - e->pal[i][2];
        long d = dr * dr + dg * dg + db * db;
        if (least < 0 || d < least)
            least = d, best = i;
    }
    e->key[h] = px + 1;
    e->val[h] = (unsigned char)best;
    return (unsigned char)best;
}

/* Sixel character ch n times. */
static void put_run(struct enc *e, int n, char ch)
{
    if (n >= 4) {
        put_num(e, '!', n);
        put(e, &ch, 1);
    } else {
        char s[3] = {ch, ch, ch};
        put(e, s, (size_t)n);
    }
}

/* Colour c's line of the band: selected (defined where first used, in percent as
 * libsixel writes them), its sixels from column 0 to its last, then cleared. */
static void put_line(struct enc *e, int c, int w)
{
    put_num(e, '#', c);
    if (!e->defined[c]) {
        put_num(e, ';', 2);
        for (int k = 0; k < 3; k++)
            put_num(e, ';', (e->pal[c][k] * 100 + 127) / 255);
        e->defined[c] = true;
    }
    unsigned char *row = e->rows + (size_t)e->slot[c] * w;
    if (e->lo[c] > 0)
        put_run(e, e->lo[c], '?');
    for (int x = e->lo[c]; x <= e->hi[c];) {
        int n = 1;
        while (x + n <= e->hi[c] && row[x + n] == row[x])
            n++;
        put_run(e, n, (char)(63 + row[x]));
        x += n;
    }
    memset(row + e->lo[c], 0, (size_t)(e->hi[c] - e->lo[c] + 1));
}

/* Rows y0 .. y0 + 5 (fewer at the bottom) as one band. */
static void band(struct enc *e, const unsigned char *data, int stride, int w, int h, int y0)
{
    e->nused = 0;
    for (int r = 0; r < 6 && y0 + r < h; r++) {
        const uint32_t *px = (const uint32_t *)(const void *)(data + (size_t)(y0 + r) * stride);
        uint32_t last = 0;
        int c = -1;
        for (int x = 0; x < w; x++) {
            uint32_t v = px[x] & 0xffffff;
            if (c < 0 || v != last)
                c = nearest(e, v), last = v;
            if (e->slot[c] < 0) {
                e->slot[c] = (short)e->nused;
                e->used[e->nused++] = (unsigned char)c;
                e->lo[c] = e->hi[c] = x;
            }
            e->rows[(size_t)e->slot[c] * w + x] |= (unsigned char)(1 << r);
            if (x < e->lo[c])
                e->lo[c] = x;
            if (x > e->hi[c])
                e->hi[c] = x;
        }
    }
    for (int i = 0; i < e->nused; i++) {
        if (i > 0)
            put(e, "$", 1);
        put_line(e, e->used[i], w);
    }
    for (int i = 0; i < e->nused; i++)
        e->slot[e->used[i]] = -1;
}

int fig_sixel_xterm256(const unsigned char *data, int stride, int w, int h,
                       struct fig_bytes *out)
{
    struct enc *e = calloc(1, sizeof *e);
    if (!e)
        return -1;
    e->rows = calloc(256, (size_t)w);
    e->out = (char *)out->data, e->cap = out->cap;
    if (!e->rows) {
        free(e);
        return -1;
    }
    palette(e->pal);
    memset(e->slot, -1, sizeof e->slot);
    put(e, "\033Pq", 3);
    put_num(e, '"', 1);
    put_num(e, ';', 1);
    put_num(e, ';', w);
    put_num(e, ';', h);
    for (int y = 0; y < h; y += 6) {
        if (y > 0)
            put(e, "-", 1);
        band(e, data, stride, w, h, y);
    }
    put(e, "\033\\", 2);
    int failed = e->failed;
    out->data = (unsigned char *)e->out, out->len = e->len, out->cap = e->cap;
    out->failed = e->failed;
    free(e->rows);
    free(e);
    return failed ? -1 : 0;
}
