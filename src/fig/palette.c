/* palette.c: the figures' colours (one per mass, the energy terms', the motor's) and the
 * format a file name asks for: what the program needs of the figures without drawing one,
 * so it stays in the program when the drawing library (figure.c and the rest, cairo's
 * users) is not loaded. */
#include "figure.h"

#include <string.h>
#include <strings.h>

enum fig_format fig_format_of(const char *path)
{
    const char *dot = path ? strrchr(path, '.') : NULL;
    if (!dot || strchr(dot, '/'))
        return FIG_FORMAT_NONE;
    if (strcasecmp(dot, ".png") == 0)
        return FIG_PNG;
    if (strcasecmp(dot, ".svg") == 0)
        return FIG_SVG;
    if (strcasecmp(dot, ".pdf") == 0)
        return FIG_PDF;
    return FIG_FORMAT_NONE;
}

/* The terminal's 256-colour palette entries (tui/term.c) as red, green, blue: the 6x6x6
 * cube's levels 0, 95, 135, 175, 215, 255. Mid tones that read on black and on white. */
static const unsigned char mass_rgb[10][3] = {
    {0, 95, 255},  {0, 135, 0},   {215, 95, 0},  {215, 0, 0},   {175, 0, 215},
    {0, 135, 135}, {175, 135, 0}, {215, 0, 175}, {135, 95, 0},  {95, 95, 175},
};

void fig_rgb(int c, bool dark, double rgb[3])
{
    static const unsigned char spring[3] = {0, 135, 0},
                               title[3] = {0, 135, 215}, warn[3] = {215, 0, 0};
    const unsigned char *p = NULL;
    double grey = dark ? 0.85 : 0.1;
    if (c >= FIG_MASS && c < FIG_MASS + 10)
        p = mass_rgb[c - FIG_MASS];
    else if (c == FIG_MOTOR) /* the foreground: white on a dark ground, black on paper */
        grey = dark ? 1.0 : 0.0;
    else if (c == FIG_SPRING)
        p = spring;
    else if (c == FIG_TITLE)
        p = title;
    else if (c == FIG_WARN)
        p = warn;
    else if (c == FIG_GRID)
        grey = dark ? 0.32 : 0.84;
    for (int i = 0; i < 3; i++)
        rgb[i] = p ? p[i] / 255.0 : grey;
}

void fig_palette_default(struct fig_palette *p, bool dark)
{
    for (int c = 0; c < FIG_COLOR_COUNT; c++)
        fig_rgb(c, dark, p->rgb[c]);
}

int fig_energy_color(int i)
{
    static const int c[7] = {FIG_MASS + 0, FIG_MASS + 1, FIG_MASS + 2, FIG_MOTOR, FIG_MASS + 3,
                             FIG_MASS + 4, FIG_WALL};
    return i >= 0 && i < 7 ? c[i] : FIG_WALL;
}
