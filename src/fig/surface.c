/* surface.c: a picture drawn with cairo, written as PNG, SVG or PDF (surface.h). */
#include "surface.h"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <errno.h>
#include <math.h>

/* cairo's writer: to the FILE. */
static cairo_status_t to_file(void *closure, const unsigned char *data, unsigned int length)
{
    return fwrite(data, 1, length, closure) == length ? CAIRO_STATUS_SUCCESS
                                                      : CAIRO_STATUS_WRITE_ERROR;
}

int fig_surface_write(FILE *fp, enum fig_format f, double w, double h, double scale,
                      const char *title, void (*draw)(cairo_t *cr, const void *arg),
                      const void *arg)
{
    cairo_surface_t *s;
    errno = 0;
    if (f == FIG_PNG)
        s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, (int)lround(w * scale),
                                       (int)lround(h * scale));
    else if (f == FIG_SVG)
        s = cairo_svg_surface_create_for_stream(to_file, fp, w, h);
    else
        s = cairo_pdf_surface_create_for_stream(to_file, fp, w, h);
    if (f == FIG_PDF && title)
        cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_TITLE, title);
    cairo_t *cr = cairo_create(s);
    if (f == FIG_PNG)
        cairo_scale(cr, scale, scale);
    draw(cr, arg);
    cairo_status_t st = cairo_status(cr);
    cairo_destroy(cr);
    if (st == CAIRO_STATUS_SUCCESS && f == FIG_PNG)
        st = cairo_surface_write_to_png_stream(s, to_file, fp);
    cairo_surface_finish(s);
    if (st == CAIRO_STATUS_SUCCESS)
        st = cairo_surface_status(s);
    cairo_surface_destroy(s);
    if (st == CAIRO_STATUS_SUCCESS)
        return ferror(fp) ? EIO : 0;
    if (st == CAIRO_STATUS_NO_MEMORY)
        return ENOMEM;
    return errno ? errno : EIO;
}
