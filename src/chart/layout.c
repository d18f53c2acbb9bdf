/* layout.c: where everything goes on the screen, as a pure function of its size and of
 * what is shown. */
#include "layout.h"

#include <math.h>
#include <stddef.h>

#define STATUS_ROWS 1
#define SCENE_ROWS 5 /* frame and three rows of chain */
#define HINT_ROWS 1

bool rect_contains(struct rect r, int y, int x)
{
    return y >= r.y && y < r.y + r.h && x >= r.x && x < r.x + r.w;
}

struct rect layout_drawing(struct rect frame)
{
    struct rect d = {frame.y + 1, frame.x + 1 + LAYOUT_LABEL_COLS,
                     frame.h - 2 - LAYOUT_XAXIS_ROWS, frame.w - 2 - LAYOUT_LABEL_COLS};
    if (d.h < 0)
        d.h = 0;
    if (d.w < 0)
        d.w = 0;
    return d;
}

/* True when a chart in frame r has a drawing area a grid plot may have. */
static bool readable(struct rect r)
{
    struct rect d = layout_drawing(r);
    return d.w >= LAYOUT_MIN_PLOT_W && d.h >= LAYOUT_MIN_PLOT_H;
}

/* Splits area a into cols x rows frames (the last column and row take the remainder). */
static void grid(struct layout *l, struct rect a, int cols, int rows)
{
    int pw = a.w / cols, ph = a.h / rows;
    for (int i = 0; i < cols * rows; i++) {
        int c = i % cols, r = i / cols;
        l->plot[i] = (struct rect){a.y + r * ph, a.x + c * pw, r == rows - 1 ? a.h - r * ph : ph,
                                   c == cols - 1 ? a.w - c * pw : pw};
    }
    l->nplots = cols * rows;
}

/* The grid: all six where each is readable, else displacement and x-v side by side or
 * stacked, else displacement alone. */
static void lay_plots(struct layout *l, int enlarged)
{
    struct rect a = l->area;
    if (enlarged >= 0 && enlarged < PLOT_COUNT) {
        l->plot[0] = a;
        l->plot_id[0] = (enum plot_id)enlarged;
        l->nplots = 1;
        return;
    }
    grid(l, a, 3, 2);
    if (readable(l->plot[0]) && readable(l->plot[5])) {
        for (int i = 0; i < PLOT_COUNT; i++)
            l->plot_id[i] = (enum plot_id)i;
        return;
    }
    l->plot_id[0] = PLOT_X;
    l->plot_id[1] = PLOT_XV;
    grid(l, a, 2, 1);
    if (readable(l->plot[0]) && readable(l->plot[1]))
        return;
    grid(l, a, 1, 2);
    if (readable(l->plot[0]) && readable(l->plot[1]))
        return;
    l->plot[0] = a;
    l->nplots = 1;
}

int layout_caption_rows(int rows)
{
    return rows >= 40 ? 9 : rows >= 30 ? 8 : 7;
}

void layout_caption(struct layout *l, int rows, int enlarged, bool view)
{
    if (l->too_small || rows <= 0)
        return;
    int top = l->area.y, h = l->area.h;
    if (rows > h - 5)
        rows = h - 5; /* a plot of a few rows is left at the smallest size */
    l->caption = (struct rect){top + h - rows, 0, rows, l->cols};
    l->area.h -= rows;
    l->controls.h -= rows;
    l->nplots = 0;
    if (!view)
        lay_plots(l, enlarged);
}

void layout_compute(struct layout *l, int cols, int rows, int enlarged, bool view)
{
    *l = (struct layout){.cols = cols, .rows = rows};
    l->too_small = cols < LAYOUT_MIN_COLS || rows < LAYOUT_MIN_ROWS;
    if (l->too_small)
        return;
    int ctrl_w = cols >= 110 ? 32 : 28;
    int top = STATUS_ROWS + SCENE_ROWS;
    int h = rows - top - HINT_ROWS;
    l->status = (struct rect){0, 0, STATUS_ROWS, cols};
    l->scene = (struct rect){STATUS_ROWS, 0, SCENE_ROWS, cols};
    l->hints = (struct rect){rows - HINT_ROWS, 0, HINT_ROWS, cols};
    l->controls = (struct rect){top, cols - ctrl_w, h, ctrl_w};
    l->area = (struct rect){top, 0, h, cols - ctrl_w};
    if (!view)
        lay_plots(l, enlarged);
    /* The chain between the wall and the motor housing, inside the scene's frame. */
    int inner = cols - 2;
    l->scene_x0 = 1 + LAYOUT_WALL_COLS;
    l->scene_cpm = (double)(inner - LAYOUT_WALL_COLS - LAYOUT_HOUSE_COLS) / LAYOUT_SCENE_SPAN;
}

void layout_scope(struct layout *l, int enlarged)
{
    if (l->too_small)
        return;
    /* 34 columns hold a row of three 9-column numbers at 80 columns; 38 give them 10. */
    int w = l->cols >= 110 ? 38 : 34;
    int grow = w - l->controls.w;
    if (grow <= 0 || l->area.w - grow < LAYOUT_LABEL_COLS + 2 + LAYOUT_MIN_PLOT_W)
        return;
    l->controls.x -= grow, l->controls.w += grow;
    l->area.w -= grow;
    if (l->nplots > 0)
        lay_plots(l, enlarged);
}

double layout_scene_col(const struct layout *l, double X)
{
    return l->scene_x0 + X * l->scene_cpm;
}

double layout_scene_metres(const struct layout *l, int col)
{
    return (col + 0.5 - l->scene_x0) / l->scene_cpm;
}

int layout_control_rows(const struct layout *l, int ncontrols)
{
    int rows = l->controls.h - 2;
    if (rows >= ncontrols + 2)
        return ncontrols;
    if (rows - 2 >= ncontrols - 3)
        return rows - 2;
    return rows >= ncontrols ? ncontrols : rows > 0 ? rows : 0;
}

int layout_control_at(const struct layout *l, int y, int x, int ncontrols, int top)
{
    struct rect c = l->controls;
    if (l->too_small || x <= c.x || x >= c.x + c.w - 1)
        return -1;
    int i = y - c.y - 1;
    return i >= 0 && i + top < ncontrols && i < layout_control_rows(l, ncontrols) ? i + top : -1;
}
