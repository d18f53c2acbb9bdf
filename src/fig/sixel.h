/* sixel.h: an image as a sixel sequence on xterm's 256 colours, encoded in one pass
 * (fig/pixels.c calls it for terminals with 256 colour registers or more). */
#ifndef SPRINGSIM_SIXEL_H
#define SPRINGSIM_SIXEL_H

#include "pixels.h"

/* The w x h image in data (cairo's RGB24: a native-endian 32-bit word a pixel, rows
 * stride bytes apart) as a whole sixel sequence (DCS ... ST) into out (emptied first),
 * each pixel in the nearest of xterm's 256 colours. Returns 0, or -1 when memory ran
 * out. */
int fig_sixel_xterm256(const unsigned char *data, int stride, int w, int h,
                       struct fig_bytes *out);

#endif
