/* lib.c: the figure library's one exported table (lib.h), read by the program after it
 * loads the library. */
#include "lib.h"

#include "save.h"

const struct fig_lib springsim_fig_lib = {
    .abi = FIG_LIB_ABI,
    .pixels = fig_pixels,
    .pixels_fit = fig_pixels_fit,
    .bytes_free = fig_bytes_free,
    .save_view = fig_save_view,
    .headless = report_headless,
    .modes = report_modes,
    .sweep = report_sweep,
    .done = fig_done,
};
