/* pixels.c: drawing areas as sixel or PNG images. Sixel images are drawn without
 * anti-aliasing on xterm's 256 colours, which hold every colour of the program exactly,
 * mapped without diffusion: a colour drawn is a colour sent, and only the colours drawn
 * are sent (in a terminal with fewer colour registers, libsixel's palette of that many
 * for each image). PNG (kitty) keeps the anti-aliased edges. */
#include "pixels.h"

#include <cairo.h>
#include <errno.h>
#include <math.h>
#include <sixel/sixel.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "paint.h"


double fig_pixel_x(double x, int cw)
{
    return (x + 0.5) * cw / 2.0;
}

double fig_pixel_y(double y, int ch)
{
    return (y + 0.5) * ch / 4.0;
}

void fig_pixels_fit(int aw, int ah, int *cw, int *ch)
{
    double w = *cw > 1 ? *cw : 1, h = *ch > 1 ? *ch : 1;
    double wide = (aw > 1 ? aw : 1) * w, high = (ah > 1 ? ah : 1) * h;
    double s = fmin(1.0, fmin(FIG_PIXELS_CELL_W / w, FIG_PIXELS_CELL_H / h));
    s = fmin(s, fmin(FIG_PIXELS_SIDE / wide, FIG_PIXELS_SIDE / high));
    s = fmin(s, sqrt(FIG_PIXELS_MAX / (wide * high)));
    *cw = (int)fmax(1.0, floor(w * s));
    *ch = (int)fmax(1.0, floor(h * s));
}

static bool grow(struct fig_bytes *b, size_t more)
{
    if (b->len + more <= b->cap)
        return true;
    size_t cap = b->cap ? b->cap : 65536;
    while (cap < b->len + more)
        cap *= 2;
    unsigned char *d = realloc(b->data, cap);
    if (!d)
        return b->failed = true, false;
    b->data = d, b->cap = cap;
    return true;
}

static void append(struct fig_bytes *b, const void *p, size_t n)
{
    if (grow(b, n)) {
        memcpy(b->data + b->len, p, n);
        b->len += n;
    }
}

void fig_bytes_free(struct fig_bytes *out)
{
    free(out->data);
    *out = (struct fig_bytes){0};
}

static int sixel_write(char *data, int size, void *priv)
{
    append(priv, data, (size_t)size);
    return size;
}

static cairo_status_t png_write(void *closure, const unsigned char *data, unsigned int length)
{
    struct fig_bytes *b = closure;
    append(b, data, length);
    return b->failed ? CAIRO_STATUS_NO_MEMORY : CAIRO_STATUS_SUCCESS;
}

/* The legend inside the image, in its last row of cells from the left (on the background,
 * over the curves): each entry a bar in its colour a cell and a half long, then its text
 * (without the mark the border's has: "━1" is a bar and "1"), so that the marks and the
 * curves are matched within the image whatever colours the terminal shows the text in. */
static void legend_marks(cairo_t *cr, const struct fig_chart *c, int cw, int ch,
                         const struct fig_palette *pal, const double bg[3])
{
    double x = 0.5 * cw, top = (c->ah - 1) * ch, mid = top + 0.5 * ch;
    double bar = fmax(2.0, floor(ch / 4.0));
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
    cairo_set_font_size(cr, 0.6 * ch);
    for (int i = 0; i < c->nlegend && x < c->aw * cw; i++) {
        int col = c->legend_color[i];
        if (col <= 0 || col >= FIG_COLOR_COUNT)
            continue;
        const char *text = c->legend[i];
        while (*text && ((unsigned char)*text >= 0x80 || *text == ' '))
            text++; /* the mark: ━, ┅, ┄, · */
        cairo_text_extents_t e;
        cairo_text_extents(cr, text, &e);
        double w = 1.5 * cw + 0.2 * cw + e.x_advance + 0.5 * cw;
        cairo_set_source_rgb(cr, bg[0], bg[1], bg[2]);
        cairo_rectangle(cr, x - 0.25 * cw, top, w, ch);
        cairo_fill(cr);
        const double *v = pal->rgb[col];
        cairo_set_source_rgb(cr, v[0], v[1], v[2]);
        cairo_rectangle(cr, x, floor(mid - 0.5 * bar), 1.5 * cw, bar);
        cairo_fill(cr);
        cairo_move_to(cr, x + 1.7 * cw, mid + 0.35 * 0.6 * ch);
        cairo_show_text(cr, text);
        x += w;
    }
}

/* Gridlines (dotted) on the ticks, the y = 0 one solid, then the strokes. */
static void paint(cairo_t *cr, const struct fig_chart *c, int cw, int ch,
                  const struct fig_palette *pal, const double bg[3])
{
    const double *grid = pal->rgb[FIG_GRID];
    cairo_set_source_rgb(cr, bg[0], bg[1], bg[2]);
    cairo_paint(cr);
    cairo_set_source_rgb(cr, grid[0], grid[1], grid[2]);
    cairo_set_line_width(cr, 1.0);
    static const double dots[] = {1.0, 3.0};
    for (int k = 0; k < c->yt.n; k++) {
        double y = floor((c->ah - c->yt.cell[k] - 0.5) * ch) + 0.5;
        cairo_set_dash(cr, dots, strtod(c->yt.label[k], NULL) == 0.0 ? 0 : 2, 0.0);
        cairo_move_to(cr, 0.0, y);
        cairo_line_to(cr, c->aw * cw, y);
        cairo_stroke(cr);
    }
    cairo_set_dash(cr, dots, 2, 0.0);
    for (int k = 0; k < c->xt.n; k++) {
        double x = floor((c->xt.cell[k] + 0.5) * cw) + 0.5;
        cairo_move_to(cr, x, 0.0);
        cairo_line_to(cr, x, c->ah * ch);
    }
    cairo_stroke(cr);
    cairo_set_dash(cr, NULL, 0, 0.0);
    if (c->strokes)
        fig_paint_strokes(cr, c->strokes, cw, ch, pal);
}

/* The sixel sequence of pixels (w x h, depth bytes each) on dither (NULL, or st a failure:
 * nothing), appended to out; dither is let go. 0 or ENOMEM. */
static int encode_on(SIXELSTATUS st, sixel_dither_t *dither, unsigned char *pixels, int w,
                     int h, int depth, struct fig_bytes *out)
{
    sixel_output_t *output = NULL;
    if (SIXEL_SUCCEEDED(st))
        st = dither ? sixel_output_new(&output, sixel_write, out, NULL) : SIXEL_BAD_ALLOCATION;
    if (SIXEL_SUCCEEDED(st))
        st = sixel_encode(pixels, w, h, depth, dither, output);
    if (output)
        sixel_output_unref(output);
    if (dither)
        sixel_dither_unref(dither);
    return SIXEL_SUCCEEDED(st) && !out->failed ? 0 : ENOMEM;
}

/* Sixel of the w x h pixels at src (cairo's RGB24 rows, stride bytes apart) on a palette
 * of a terminal's `registers` colours (2 to 255) that libsixel chooses for the image
 * (median cut); rgb holds the pixels as libsixel takes them. */
static int encode_chosen(const unsigned char *src, int stride, int w, int h, int registers,
                         struct fig_bytes *rgb, struct fig_bytes *out)
{
    size_t need = (size_t)w * (size_t)h * 3;
    rgb->len = 0;
    if (!grow(rgb, need))
        return ENOMEM;
    for (int y = 0; y < h; y++) {
        const uint32_t *row = (const uint32_t *)(const void *)(src + (size_t)y * stride);
        for (int x = 0; x < w; x++) {
            unsigned char *p = rgb->data + ((size_t)y * w + x) * 3;
            p[0] = (unsigned char)(row[x] >> 16);
            p[1] = (unsigned char)(row[x] >> 8);
            p[2] = (unsigned char)row[x];
        }
    }
    sixel_dither_t *dither = NULL;
    SIXELSTATUS st = sixel_dither_new(&dither, registers, NULL);
    if (SIXEL_SUCCEEDED(st))
        st = sixel_dither_initialize(dither, rgb->data, w, h, SIXEL_PIXELFORMAT_RGB888,
                                     SIXEL_LARGE_AUTO, SIXEL_REP_AUTO, SIXEL_QUALITY_AUTO);
    if (SIXEL_SUCCEEDED(st)) {
        sixel_dither_set_diffusion_type(dither, SIXEL_DIFFUSE_NONE);
        sixel_dither_set_pixelformat(dither, SIXEL_PIXELFORMAT_RGB888);
    }
    return encode_on(st, dither, rgb->data, w, h, 3, out);
}

/* Colours met so far and the nearest of xterm's 256 to each, direct-mapped by a hash of
 * the colour (a colour that finds its slot taken is searched for again). */
#define NEAREST_SLOTS 4096
static uint32_t nearest_key[NEAREST_SLOTS]; /* 0x1000000 | RGB: a colour's slot, 0: empty */
static uint8_t nearest_index[NEAREST_SLOTS];
static unsigned char xterm256[256 * 3]; /* libsixel's built-in palette */
static bool have_xterm256;

/* The index of xterm's colour nearest to rgb (0xRRGGBB), the least squared distance
 * (the first such), as libsixel's own look-up chooses. */
static int nearest_xterm(uint32_t rgb)
{
    uint32_t key = 0x1000000u | rgb;
    unsigned slot = (unsigned)((key * 2654435761u) >> 20) & (NEAREST_SLOTS - 1);
    if (nearest_key[slot] == key)
        return nearest_index[slot];
    int r = (int)(rgb >> 16 & 0xFF), g = (int)(rgb >> 8 & 0xFF), b = (int)(rgb & 0xFF);
    int best = 0;
    long least = -1;
    for (int i = 0; i < 256; i++) {
        long dr = r - xterm256[3 * i], dg = g - xterm256[3 * i + 1], db = b - xterm256[3 * i + 2];
        long d = dr * dr + dg * dg + db * db;
        if (least < 0 || d < least)
            least = d, best = i;
    }
    nearest_key[slot] = key;
    nearest_index[slot] = (uint8_t)best;
    return best;
}

/* Sixel of the w x h pixels at src on xterm's 256 colours: the program's colours are among
 * them (its 6x6x6 cube); another (a terminal's own palette, the legend's text) takes the
 * nearest. The pixels are mapped here, each to its colour's register, and only the
 * colours used are defined: libsixel then encodes a palette of those few, not 256 (each
 * of which it would look for in every band of six rows), and looks nothing up. idx
 * holds the registers. */
static int encode_xterm(const unsigned char *src, int stride, int w, int h,
                        struct fig_bytes *idx, struct fig_bytes *out)
{
    if (!have_xterm256) {
        sixel_dither_t *builtin = sixel_dither_get(SIXEL_BUILTIN_XTERM256);
        if (!builtin)
            return ENOMEM;
        memcpy(xterm256, sixel_dither_get_palette(builtin), sizeof xterm256);
        sixel_dither_unref(builtin);
        have_xterm256 = true;
    }
    idx->len = 0;
    if (!grow(idx, (size_t)w * (size_t)h))
        return ENOMEM;
    int reg[256], used = 0;
    unsigned char palette[256 * 3];
    for (int i = 0; i < 256; i++)
        reg[i] = -1;
    uint32_t last = 0x1000000u; /* no colour: the next pixel is looked up */
    int last_reg = 0;
    for (int y = 0; y < h; y++) {
        const uint32_t *row = (const uint32_t *)(const void *)(src + (size_t)y * stride);
        unsigned char *o = idx->data + (size_t)y * w;
        for (int x = 0; x < w; x++) {
            uint32_t rgb = row[x] & 0xFFFFFFu;
            if (rgb != last) {
                int c = nearest_xterm(rgb);
                if (reg[c] < 0) {
                    memcpy(palette + 3 * used, xterm256 + 3 * c, 3);
                    reg[c] = used++;
                }
                last = rgb, last_reg = reg[c];
            }
            o[x] = (unsigned char)last_reg;
        }
    }
    sixel_dither_t *dither = NULL;
    SIXELSTATUS st = sixel_dither_new(&dither, used, NULL);
    if (SIXEL_SUCCEEDED(st)) {
        sixel_dither_set_palette(dither, palette);
        sixel_dither_set_pixelformat(dither, SIXEL_PIXELFORMAT_PAL8);
    }
    return encode_on(st, dither, idx->data, w, h, 1, out);
}

int fig_pixels(const struct fig_chart *c, int cw, int ch, const struct fig_palette *pal,
               const double bg[3], bool marks, enum fig_encoding e, int registers,
               struct fig_bytes *out, struct fig_bytes *scratch)
{
    int w = c->aw * cw, h = c->ah * ch;
    out->len = 0;
    out->failed = false;
    if (w <= 0 || h <= 0)
        return EINVAL;
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h);
    cairo_t *cr = cairo_create(s);
    /* Sixel without blends: lines leave the image only the colours drawn, each sent
     * exactly. With few colour registers libsixel's palette then keeps them apart (to its
     * 5 bits a channel: white comes out #f8f8f8; with the blends, mass 1's blue was lost
     * in an average); on xterm's 256 an image holds a handful of colours, not the hundred
     * or more of its blends, and libsixel encodes it about ten times as fast (it goes
     * over every band of six rows once for each colour) in a third of the bytes. */
    bool few = e == FIG_SIXEL && registers >= 2 && registers < 256;
    if (e == FIG_SIXEL)
        cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
    paint(cr, c, cw, ch, pal, bg);
    if (marks)
        legend_marks(cr, c, cw, ch, pal, bg);
    cairo_status_t cs = cairo_status(cr);
    cairo_destroy(cr);
    cairo_surface_flush(s);
    int err = cs == CAIRO_STATUS_SUCCESS ? 0 : ENOMEM;
    if (!err && e == FIG_KITTY_PNG) {
        err = cairo_surface_write_to_png_stream(s, png_write, out) == CAIRO_STATUS_SUCCESS
                  ? 0 : ENOMEM;
    } else if (!err) {
        const unsigned char *src = cairo_image_surface_get_data(s);
        int stride = cairo_image_surface_get_stride(s);
        err = few ? encode_chosen(src, stride, w, h, registers, scratch, out)
                  : encode_xterm(src, stride, w, h, scratch, out);
    }
    cairo_surface_destroy(s);
    return err;
}
