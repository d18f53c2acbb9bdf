/* pixels.h: a chart's drawing area as an image for the terminal: painted with cairo (the
 * background, gridlines on the ticks, the zero line, the strokes) at the terminal's cell
 * size, then encoded as sixel (libsixel, on xterm's 256 colours, which hold the program's)
 * or fewer where the terminal has fewer colour registers, or as PNG (for kitty's protocol). No curses here:
 * tui/graphics.c sends the bytes. */
#ifndef SPRINGSIM_PIXELS_H
#define SPRINGSIM_PIXELS_H

#include <stdbool.h>
#include <stddef.h>

#include "view_picture.h"

/* Bytes grown as needed and kept for the next image. */
struct fig_bytes {
    unsigned char *data;
    size_t len, cap;
    bool failed; /* memory ran out */
};

enum fig_encoding { FIG_SIXEL, FIG_KITTY_PNG };

/* The image of c's drawing area (aw * cw by ah * ch pixels) on the background bg (red,
 * green, blue, 0..1) in the colours of pal (the ones the terminal shows the text in, so a
 * legend's mark and its curve are one colour), encoded e into out (emptied first): a
 * whole sixel sequence (DCS ... ST), or the PNG file; scratch holds the pixels on their
 * way (kept for the next image). With marks (the terminal's colours not known), the
 * legend is drawn in the image too, its last row of cells: each entry's mark (a bar) and
 * text in its colour, so marks and curves are matched within it. Sixel is drawn without
 * anti-aliasing, on xterm's 256 colours (only those drawn defined in the image), or, for a
 * terminal with 2 to 255 colour registers, on a palette of that many that libsixel
 * chooses for the image. PNG is anti-aliased.
 * Returns 0 or an errno value. */
int fig_pixels(const struct fig_chart *c, int cw, int ch, const struct fig_palette *pal,
               const double bg[3], bool marks, enum fig_encoding e, int registers,
               struct fig_bytes *out, struct fig_bytes *scratch);

/* What a terminal says of its cells is not trusted: a cell is drawn with at most
 * FIG_PIXELS_CELL_W x FIG_PIXELS_CELL_H pixels and an image has at most FIG_PIXELS_SIDE
 * pixels a side and FIG_PIXELS_MAX in all (a plot enlarged on a full-HD screen, at its
 * own size), so that the program's peak memory (an image's surface, pixels and encoding
 * with the rest) stays near 40 MB whatever the terminal says: at 2048 x 2048 it reached
 * 52 MB, and 66 MB once, too near the 64 MB meant. */
#define FIG_PIXELS_CELL_W 64
#define FIG_PIXELS_CELL_H 128
#define FIG_PIXELS_SIDE 4096
#define FIG_PIXELS_MAX (2048 * 1024)

/* The cell size (*cw x *ch pixels, each at least 1) an area of aw x ah cells is drawn
 * with: as given, or scaled down by one factor (the cell's shape kept, to whole pixels)
 * until it is within the caps above. */
void fig_pixels_fit(int aw, int ah, int *cw, int *ch);

/* The pixel row and column of dot coordinate (x, y) in such an image (the centre of the
 * line drawn through it): ((x + 0.5) cw / 2, (y + 0.5) ch / 4). */
double fig_pixel_x(double x, int cw);
double fig_pixel_y(double y, int ch);

/* Frees out's memory. */
void fig_bytes_free(struct fig_bytes *out);

#endif
