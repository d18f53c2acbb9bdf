/* sixelcheck.c: the images in what a program wrote to its terminal (pixterm's OUT),
 * decoded with libsixel's decoder (sixel) or cairo's PNG reader (kitty's base64 chunks
 * joined, decoded with GLib). One line an image: "sixel|kitty ROW COL WIDTH HEIGHT",
 * ROW and COL the cell it was placed at (the CSI H before it, 1-based), then for each
 * colour asked " TOP:BOTTOM:COUNT": the first and last pixel row holding that colour
 * (within 8 of each of red, green and blue) and how many pixels do (-1:-1:0: none); for
 * sixel, last, " colours=K": how many different colours the decoded image holds.
 * usage: sixelcheck OUT [RRGGBB...] */
#include <cairo.h>
#include <glib.h>
#include <sixel/sixel.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int ncolors;
static unsigned want[16][3];

/* Prints the colour report of an image of w x h pixels, pixel (x, y) given by get, then
 * distinct (when not negative) as its count of different colours. */
static void report(int w, int h, void (*get)(const void *, int, int, unsigned *), const void *img,
                   int distinct)
{
    for (int c = 0; c < ncolors; c++) {
        int top = -1, bottom = -1;
        long count = 0;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                unsigned p[3];
                get(img, x, y, p);
                if (abs((int)p[0] - (int)want[c][0]) <= 8 && abs((int)p[1] - (int)want[c][1]) <= 8 &&
                    abs((int)p[2] - (int)want[c][2]) <= 8) {
                    if (top < 0)
                        top = y;
                    bottom = y;
                    count++;
                }
            }
        printf(" %d:%d:%ld", top, bottom, count);
    }
    if (distinct >= 0)
        printf(" colours=%d", distinct);
    printf("\n");
}

struct indexed {
    const unsigned char *pixels, *palette;
    int w;
};

static void get_indexed(const void *img, int x, int y, unsigned *p)
{
    const struct indexed *ix = img;
    const unsigned char *c = ix->palette + 3 * ix->pixels[(size_t)y * ix->w + x];
    p[0] = c[0], p[1] = c[1], p[2] = c[2];
}

/* How many different colours (RGB) the pixels of an indexed image hold. */
static int distinct_colours(const struct indexed *ix, int w, int h)
{
    static bool used[256];
    unsigned seen[256];
    int n = 0;
    memset(used, 0, sizeof used);
    for (size_t i = 0; i < (size_t)w * (size_t)h; i++)
        used[ix->pixels[i]] = true;
    for (int k = 0; k < 256; k++) {
        if (!used[k])
            continue;
        const unsigned char *c = ix->palette + 3 * k;
        unsigned rgb = (unsigned)c[0] << 16 | (unsigned)c[1] << 8 | c[2];
        int j = 0;
        while (j < n && seen[j] != rgb)
            j++;
        if (j == n)
            seen[n++] = rgb;
    }
    return n;
}

static void get_cairo(const void *img, int x, int y, unsigned *p)
{
    cairo_surface_t *s = (cairo_surface_t *)img;
    const unsigned char *d = cairo_image_surface_get_data(s);
    unsigned v = *(const unsigned *)(const void *)(d + (size_t)y * cairo_image_surface_get_stride(s) + 4 * x);
    p[0] = (v >> 16) & 255, p[1] = (v >> 8) & 255, p[2] = v & 255;
}

struct png_read {
    const unsigned char *p;
    size_t left;
};

static cairo_status_t png_in(void *closure, unsigned char *data, unsigned int length)
{
    struct png_read *r = closure;
    if (length > r->left)
        return CAIRO_STATUS_READ_ERROR;
    memcpy(data, r->p, length);
    r->p += length, r->left -= length;
    return CAIRO_STATUS_SUCCESS;
}

/* The cell of the last "ESC [ row ; col H" before at. */
static void last_position(const char *buf, const char *at, int *row, int *col)
{
    *row = *col = 0;
    for (const char *p = at; p > buf; p--)
        if (p[0] == '\033' && p[1] == '[' && sscanf(p, "\033[%d;%dH", row, col) == 2) {
            const char *e = p + 2 + strspn(p + 2, "0123456789;");
            if (*e == 'H')
                return;
        }
    *row = *col = 0;
}

int main(int argc, char **argv)
{
    if (argc < 2)
        return 2;
    FILE *f = fopen(argv[1], "rb");
    if (!f)
        return 1;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *buf = malloc((size_t)n + 1);
    if (!buf || fread(buf, 1, (size_t)n, f) != (size_t)n)
        return 1;
    fclose(f);
    buf[n] = '\0';
    for (long i = 0; i < n; i++)
        if (!buf[i])
            buf[i] = ' ';
    for (int i = 2; i < argc && ncolors < 16; i++, ncolors++)
        sscanf(argv[i], "%2x%2x%2x", &want[ncolors][0], &want[ncolors][1], &want[ncolors][2]);
    for (char *p = buf; (p = strstr(p, "\033P"));) {
        char *end = strstr(p, "\033\\");
        if (!end)
            break;
        int row, col, w, h, ncol;
        last_position(buf, p, &row, &col);
        unsigned char *pixels = NULL, *palette = NULL;
        if (sixel_decode_raw((unsigned char *)p, (int)(end + 2 - p), &pixels, &w, &h, &palette,
                             &ncol, NULL) == SIXEL_OK) {
            printf("sixel %d %d %d %d", row, col, w, h);
            struct indexed ix = {pixels, palette, w};
            report(w, h, get_indexed, &ix, distinct_colours(&ix, w, h));
        } else {
            printf("sixel %d %d undecodable\n", row, col);
        }
        free(pixels);
        free(palette);
        p = end + 2;
    }
    /* Kitty: a=T starts an image, m=1 says more chunks follow. */
    for (char *p = buf; (p = strstr(p, "\033_Ga=T,"));) {
        int row, col;
        last_position(buf, p, &row, &col);
        GString *b64 = g_string_new(NULL);
        for (char *q = p;;) {
            char *semi = strchr(q, ';'), *end = strstr(q, "\033\\");
            if (!semi || !end)
                break;
            g_string_append_len(b64, semi + 1, end - semi - 1);
            bool more = strstr(q, "m=1;") && strstr(q, "m=1;") < semi;
            q = end + 2;
            if (!more || strncmp(q, "\033_G", 3) != 0)
                break;
        }
        gsize len;
        guchar *png = g_base64_decode(b64->str, &len);
        struct png_read r = {png, len};
        cairo_surface_t *s = cairo_image_surface_create_from_png_stream(png_in, &r);
        if (cairo_surface_status(s) == CAIRO_STATUS_SUCCESS) {
            cairo_surface_flush(s);
            printf("kitty %d %d %d %d", row, col, cairo_image_surface_get_width(s),
                   cairo_image_surface_get_height(s));
            report(cairo_image_surface_get_width(s), cairo_image_surface_get_height(s), get_cairo,
                   s, -1);
        } else {
            printf("kitty %d %d undecodable\n", row, col);
        }
        cairo_surface_destroy(s);
        g_free(png);
        g_string_free(b64, TRUE);
        p += 7;
    }
    free(buf);
    return 0;
}
