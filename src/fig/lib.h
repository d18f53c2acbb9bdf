/* lib.h: the figure library (springsim-fig.so: figure.c and every file that draws with
 * cairo or encodes with libsixel) as the program sees it: one table of the calls it makes,
 * found by fig_lib() the first time a figure or a pixel plot is wanted. A run that draws
 * neither never loads cairo, fontconfig, libsixel and the libraries they pull in (half
 * of the program's libraries, and a megabyte or two of its memory). */
#ifndef SPRINGSIM_FIG_LIB_H
#define SPRINGSIM_FIG_LIB_H

#include <stdio.h>

#include "app/app.h"
#include "pixels.h"
#include "report.h"

/* Changes whenever the table below does: a library of another build is refused. */
#define FIG_LIB_ABI "springsim-fig 4 " VERSION

/* The library's file name, in the program's directory or FIGLIBDIR. */
#define FIG_LIB_FILE "springsim-fig.so"

struct fig_lib {
    const char *abi; /* FIG_LIB_ABI of the build that made it */
    int (*pixels)(const struct fig_chart *c, int cw, int ch, const struct fig_palette *pal,
                  const double bg[3], bool marks, enum fig_encoding e, int registers,
                  struct fig_bytes *out, struct fig_bytes *scratch);
    void (*pixels_fit)(int aw, int ah, int *cw, int *ch);
    void (*bytes_free)(struct fig_bytes *out);
    unsigned (*save_view)(struct app *app, const struct fig_chart *c, int n,
                          const char *name);
    int (*headless)(FILE *fp, enum fig_format f, struct report_data *d, int n, bool motor,
                    bool energy, double t0, double t_end, const struct report_look *look);
    int (*modes)(FILE *fp, enum fig_format f, const struct model *m, const double *freq,
                 const double *shapes, const struct report_look *look);
    int (*sweep)(FILE *fp, enum fig_format f, struct report_data *d, int n,
                 const struct report_look *look);
    void (*done)(void);
};

/* The table's name in the library, and the table. */
#define FIG_LIB_SYMBOL "springsim_fig_lib"
extern const struct fig_lib springsim_fig_lib;

/* Where to look for the library first: the running program's directory (a build tree's
 * library beside its program), before FIGLIBDIR. Called once at start. */
void fig_lib_where(const char *exe_dir);

/* The library's table, loaded the first time; NULL when it cannot be, with the reason in
 * why (a sentence naming the file and what went wrong, the same each later call). */
const struct fig_lib *fig_lib(char *why, size_t len);

/* The library's table if it was loaded, else NULL (it is not loaded here). */
const struct fig_lib *fig_lib_loaded(void);

#endif
