/* surface.c: a picture drawn with cairo, written as PNG, SVG or PDF (surface.h). The
 * title goes in the PDF's metadata and in the SVG's <title> element: cairo draws text as
 * glyph outlines, so without it the SVG would not hold its title as text. */
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

/* An SVG on its way to fp: title (or NULL) to be written as the first element inside the
 * root <svg ...> tag, once that tag has gone by. */
struct svg_sink {
    FILE *fp;
    const char *title;
    int seen; /* characters of "<svg" matched so far; 4: inside the root tag */
    bool done;
};

/* The title, its &, < and > as entities, in a <title> element. */
static void put_title(FILE *fp, const char *title)
{
    fputs("\n<title>", fp);
    for (const char *c = title; *c; c++) {
        if (*c == '&')
            fputs("&amp;", fp);
        else if (*c == '<')
            fputs("&lt;", fp);
        else if (*c == '>')
            fputs("&gt;", fp);
        else if ((unsigned char)*c >= 0x20 || *c == '\t')
            fputc(*c, fp);
    }
    fputs("</title>", fp);
}

/* cairo's writer for an SVG: the bytes as they come, the title put in after the root tag
 * (cairo writes the tag in pieces, so it is found across calls). */
static cairo_status_t to_svg(void *closure, const unsigned char *data, unsigned int length)
{
    struct svg_sink *sink = closure;
    unsigned int k = 0;
    for (; !sink->done && k < length; k++) {
        if (sink->seen == 4 && data[k] == '>') {
            if (fwrite(data, 1, k + 1, sink->fp) != k + 1)
                return CAIRO_STATUS_WRITE_ERROR;
            put_title(sink->fp, sink->title);
            sink->done = true;
            data += k + 1, length -= k + 1;
            break;
        }
        if (sink->seen < 4)
            sink->seen = data[k] == "<svg"[sink->seen] ? sink->seen + 1 : data[k] == '<';
    }
    return to_file(sink->fp, data, length);
}

int fig_surface_write(FILE *fp, enum fig_format f, double w, double h, double scale,
                      const char *title, void (*draw)(cairo_t *cr, const void *arg),
                      const void *arg)
{
    cairo_surface_t *s;
    struct svg_sink sink = {fp, title, 0, title == NULL};
    errno = 0;
    if (f == FIG_PNG)
        s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, (int)lround(w * scale),
                                       (int)lround(h * scale));
    else if (f == FIG_SVG)
        s = cairo_svg_surface_create_for_stream(to_svg, &sink, w, h);
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
