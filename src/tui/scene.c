/* scene.c: the chain drawn to scale. Springs are braille zig-zags (a row of / and \
 * without UTF-8), a spring with a damper beside it has a dashpot drawn below it; blocks
 * have sub-cell edges (eighth blocks), heavier ones stand taller, and every block is
 * centred on the springs' line; the mass the force input acts on carries an arrow the
 * way the force pushes now. */
#include "scene.h"

#include <math.h>
#include <stdio.h>

#include "../app/ghost.h"
#include "draw.h"
#include "term.h"

#define CHAIN_ROW 2 /* the springs' line: the scene's middle row of three */

bool scene_place(struct scene *s, const struct layout *l)
{
    canvas_free(s->canvas);
    s->canvas = l->too_small ? NULL : canvas_new(l->scene.w - 2, 3);
    return s->canvas != NULL;
}

void scene_free(struct scene *s)
{
    canvas_free(s->canvas);
    s->canvas = NULL;
}

/* A zig-zag spring between physical positions a and b on the scene canvas. */
static void draw_spring(const struct scene *s, const struct layout *l, double a, double b,
                        uint8_t color)
{
    int x0 = (int)lround(2.0 * (layout_scene_col(l, a) - l->scene.x - 1));
    int x1 = (int)lround(2.0 * (layout_scene_col(l, b) - l->scene.x - 1));
    int mid = 5, amp = 3; /* dot rows 2..8 of 12 */
    if (x1 - x0 < 6) {
        canvas_line(s->canvas, x0, mid, x1, mid, color);
        return;
    }
    const int zigs = 8;
    int px = x0, py = mid;
    for (int k = 1; k <= 2 * zigs + 1; k++) {
        int x = x0 + (int)lround((double)(x1 - x0) * k / (2 * zigs + 2));
        int y = mid + ((k % 2) ? -amp : amp);
        canvas_line(s->canvas, px, py, x, y, color);
        px = x, py = y;
    }
    canvas_line(s->canvas, px, py, x1, mid, color);
}

/* A dashpot below the spring between physical positions a and b: a rod from each end, one
 * into a cup (dot rows 9 to 11, under the zig-zag's 2 to 8). */
static void draw_dashpot(const struct scene *s, const struct layout *l, double a, double b,
                         uint8_t color)
{
    int x0 = (int)lround(2.0 * (layout_scene_col(l, a) - l->scene.x - 1));
    int x1 = (int)lround(2.0 * (layout_scene_col(l, b) - l->scene.x - 1));
    int mid = (x0 + x1) / 2;
    if (x1 - x0 < 8) {
        canvas_line(s->canvas, x0, 10, x1, 10, color);
        return;
    }
    canvas_line(s->canvas, x0, 10, mid, 10, color);      /* the piston's rod */
    canvas_line(s->canvas, mid, 9, mid, 11, color);      /* the piston */
    canvas_line(s->canvas, mid - 2, 9, mid + 3, 9, color); /* the cup, open to the left */
    canvas_line(s->canvas, mid - 2, 11, mid + 3, 11, color);
    canvas_line(s->canvas, mid + 3, 9, mid + 3, 11, color);
    canvas_line(s->canvas, mid + 3, 10, x1, 10, color);  /* the cup's rod */
}

/* One cell of a block covering [lo, hi) of cell x across, in a row filled `fill` (0..1)
 * from its bottom (up = false) or its top (up = true). */
static void block_cell(int y, int x, double lo, double hi, double fill, bool from_top)
{
    static const char *const left_eighths[9] = {" ", "▏", "▎", "▍", "▌", "▋", "▊", "▉", "█"};
    static const char *const lower_eighths[9] = {" ", "▁", "▂", "▃", "▄", "▅", "▆", "▇", "█"};
    if (fill < 0.94) {
        int e = (int)lround(fill * 8);
        if (from_top) {
            /* The top e eighths: the lower 8 - e, reversed. */
            attron(A_REVERSE);
            mvaddstr(y, x, lower_eighths[8 - e]);
            attroff(A_REVERSE);
        } else {
            mvaddstr(y, x, lower_eighths[e]);
        }
    } else if (hi - lo > 0.94) {
        mvaddstr(y, x, "█");
    } else if (lo - x < 0.06) {
        mvaddstr(y, x, left_eighths[(int)lround((hi - lo) * 8)]);
    } else {
        /* Covers the right part: the uncovered left part, reversed. */
        int e = (int)lround((lo - x) * 8);
        attron(A_REVERSE);
        mvaddstr(y, x, e <= 0 ? " " : left_eighths[e > 8 ? 8 : e]);
        attroff(A_REVERSE);
    }
}

/* A block from physical a to b, height rows tall (1 to 3) centred on the chain's row,
 * with its label on that row. */
static void draw_block(const struct layout *l, double a, double b, double height, attr_t attr,
                       const char *label, bool selected)
{
    double c0 = layout_scene_col(l, a), c1 = layout_scene_col(l, b);
    int first = (int)floor(c0), last = (int)ceil(c1) - 1;
    int xmin = l->scene.x + 1, xmax = l->scene.x + l->scene.w - 2;
    double extra = 0.5 * (height - 1.0); /* of the rows above and below */
    for (int row = 1; row <= 3; row++) {
        int y = l->scene.y + row;
        double fill = row == CHAIN_ROW ? 1.0 : extra;
        if (fill <= 0.06)
            continue;
        attron(attr);
        for (int x = first; x <= last; x++) {
            double lo = fmax(c0, x), hi = fmin(c1, x + 1.0);
            if (x < xmin || x > xmax || hi <= lo)
                continue;
            if (!term_utf8())
                mvaddch(y, x, selected ? '@' : (row == CHAIN_ROW ? '=' : '#'));
            else
                block_cell(y, x, lo, hi, fill, row > CHAIN_ROW);
        }
        attroff(attr);
    }
    if (!label)
        return;
    int len = draw_width(label);
    int x = (int)floor(0.5 * (c0 + c1)) - (len - 1) / 2;
    if (x >= xmin && x + len - 1 <= xmax) {
        attr_t la = attr | A_REVERSE | A_BOLD | (selected ? A_UNDERLINE : 0);
        draw_text_attr(l->scene.y + CHAIN_ROW, x, len, la, label);
    }
}

/* The ghost's blocks (ghost.h): outlines in each mass's colour, dim, drawn before the
 * live chain's blocks, which cover them where the two are together. Each spans the cells
 * and rows its live twin would, so an unchanged ghost is hidden. */
static void draw_ghost(const struct layout *l, const struct app *app)
{
    const struct ghost *g = app->ghost;
    if (!g)
        return;
    const struct model *m = g->model;
    const double *x = sim_x(g->sim);
    double w = model_block_width(m), mmax = 0.0;
    bool utf8 = term_utf8();
    int xmin = l->scene.x + 1, xmax = l->scene.x + l->scene.w - 2;
    for (int i = 0; i < m->n; i++)
        mmax = fmax(mmax, m->m[i]);
    for (int i = 0; i < m->n; i++) {
        double X = model_equilibrium(m, i) + x[i];
        double c0 = layout_scene_col(l, X - 0.5 * w), c1 = layout_scene_col(l, X + 0.5 * w);
        int first = (int)floor(c0), last = (int)ceil(c1) - 1;
        /* Rows above and below the chain's where the live block would fill any. */
        bool tall = 0.5 * (fmax(1.0, 3.0 * sqrt(m->m[i] / mmax)) - 1.0) > 0.06;
        attron(term_mass_attr(i) | A_DIM);
        for (int row = tall ? 1 : CHAIN_ROW; row <= (tall ? 3 : CHAIN_ROW); row++) {
            int y = l->scene.y + row;
            for (int c = first; c <= last; c++) {
                if (c < xmin || c > xmax)
                    continue;
                bool left = c == first, right = c == last, edge = left || right;
                const char *s;
                if (row == CHAIN_ROW && !tall)
                    s = left ? (utf8 ? "▕" : "[") : right ? (utf8 ? "▏" : "]") : NULL;
                else if (row == CHAIN_ROW)
                    s = edge ? (utf8 ? "│" : "|") : NULL;
                else if (row < CHAIN_ROW)
                    s = !utf8 ? (edge ? "+" : "-") : left ? "┌" : right ? "┐" : "─";
                else
                    s = !utf8 ? (edge ? "+" : "-") : left ? "└" : right ? "┘" : "─";
                if (s)
                    mvaddstr(y, c, s);
            }
        }
        attroff(term_mass_attr(i) | A_DIM);
    }
}

/* The springs, on the canvas (or as / and \ without UTF-8). */
static void draw_springs(struct scene *s, const struct layout *l, const struct app *app,
                         const struct selection *sel, double end)
{
    const struct model *m = app->model;
    const double *x = sim_x(app->sim);
    double w = model_block_width(m);
    struct rect r = l->scene;
    canvas_clear(s->canvas);
    for (int j = 0; j <= m->n; j++) {
        if (j == m->n && m->boundary == BOUNDARY_FREE)
            break;
        double a = j == 0 ? 0.0 : model_equilibrium(m, j - 1) + x[j - 1] + 0.5 * w;
        double b = j == m->n ? end : model_equilibrium(m, j) + x[j] - 0.5 * w;
        if (b <= a)
            continue;
        bool hot = select_spring(sel) == j;
        bool coil = m->k[j] != 0.0; /* a spring of k = 0 is missing: no coil drawn */
        if (term_utf8()) {
            if (coil)
                draw_spring(s, l, a, b, hot ? PAIR_TITLE : PAIR_SPRING);
            if (m->cs[j] > 0.0)
                draw_dashpot(s, l, a, b, hot ? PAIR_TITLE : PAIR_SPRING);
            continue;
        }
        int c0 = (int)lround(layout_scene_col(l, a)), c1 = (int)lround(layout_scene_col(l, b));
        attron(term_attr(hot ? PAIR_TITLE : PAIR_SPRING));
        for (int c = c0; coil && c < c1; c++)
            if (c > r.x && c < r.x + r.w - 1)
                mvaddch(r.y + CHAIN_ROW, c, ((c - c0) % 2) ? '\\' : '/');
        int cm = (c0 + c1) / 2;
        for (int c = c0; m->cs[j] > 0.0 && c < c1; c++) /* the dashpot: --=[-- */
            if (c > r.x && c < r.x + r.w - 1)
                mvaddch(r.y + CHAIN_ROW + 1, c, c == cm ? '[' : c == cm - 1 ? '=' : '-');
        attroff(term_attr(hot ? PAIR_TITLE : PAIR_SPRING));
    }
    if (term_utf8()) {
        /* The blank cells between the coils take the springs' colour too: a colour
         * change costs more bytes than the character, and most frames change these rows. */
        attron(term_attr(PAIR_SPRING));
        for (int row = 1; row <= 3; row++)
            mvhline(r.y + row, r.x + 3, ' ', r.w - 4);
        attroff(term_attr(PAIR_SPRING));
        draw_canvas(s->canvas, r.y + 1, r.x + 1);
    }
}

/* The right end: piston and motor housing, or a wall. */
static void draw_end(const struct layout *l, const struct model *m, double end)
{
    struct rect r = l->scene;
    bool utf8 = term_utf8();
    int hx = r.x + r.w - 1 - LAYOUT_HOUSE_COLS;
    attr_t wall = term_attr(PAIR_WALL);
    if (m->boundary == BOUNDARY_MOTOR) {
        attron(wall);
        for (int c = (int)ceil(layout_scene_col(l, end)); c < hx; c++)
            mvaddstr(r.y + CHAIN_ROW, c, utf8 ? "═" : "=");
        attroff(wall);
        draw_block(l, end, end + 0.12, 3.0, wall | A_BOLD, NULL, false);
        attron(wall);
        draw_text(r.y + 1, hx, LAYOUT_HOUSE_COLS, utf8 ? "┌───────┐" : "+-------+");
        draw_text(r.y + 2, hx, LAYOUT_HOUSE_COLS, utf8 ? "┤MOTOR  │" : "|MOTOR  |");
        draw_text(r.y + 3, hx, LAYOUT_HOUSE_COLS, utf8 ? "└───────┘" : "+-------+");
        attroff(wall);
        draw_text_attr(r.y + 2, hx + 7, 1, term_attr(PAIR_MOTOR) | A_BOLD, "●");
    } else if (m->boundary == BOUNDARY_WALL) {
        int c = (int)lround(layout_scene_col(l, MODEL_LENGTH));
        for (int row = 1; row <= 3; row++)
            draw_text_attr(r.y + row, c, 2, wall, utf8 ? "▓▓" : "##");
    }
}

void scene_draw(struct scene *s, const struct layout *l, const struct app *app,
                const struct selection *sel)
{
    const struct model *m = app->model;
    const double *x = sim_x(app->sim);
    double w = model_block_width(m);
    struct rect r = l->scene;
    draw_frame(r, "Chain", false);
    for (int row = 1; row <= 3; row++)
        draw_text_attr(r.y + row, r.x + 1, LAYOUT_WALL_COLS, term_attr(PAIR_WALL),
                       term_utf8() ? "▓▓" : "##");
    double end = MODEL_LENGTH + (m->boundary == BOUNDARY_MOTOR ? sim_end_position(app->sim) : 0.0);
    if (s->canvas)
        draw_springs(s, l, app, sel, end);
    draw_end(l, m, end);
    draw_ghost(l, app);
    /* Masses to scale, each with its number; heavier ones stand taller. */
    double mmax = 0.0;
    for (int i = 0; i < m->n; i++)
        mmax = fmax(mmax, m->m[i]);
    for (int i = 0; i < m->n; i++) {
        double X = model_equilibrium(m, i) + x[i];
        char label[12];
        snprintf(label, sizeof label, "%d", i + 1);
        double height = fmax(1.0, 3.0 * sqrt(m->m[i] / mmax));
        draw_block(l, X - 0.5 * w, X + 0.5 * w, height, term_mass_attr(i), label,
                   select_mass(sel) == i);
    }
    if (model_forced(m) && m->force_on < m->n) {
        /* The force's arrow on the top row over its mass, the way it pushes now. */
        double f = model_force(m, sim_time(app->sim));
        double X = model_equilibrium(m, m->force_on) + x[m->force_on];
        int c = (int)lround(layout_scene_col(l, X)) - 1;
        const char *arrow = f > 0.0   ? (term_utf8() ? "F→" : "F>")
                            : f < 0.0 ? (term_utf8() ? "←F" : "<F")
                                      : "F ";
        if (c > r.x && c + 1 < r.x + r.w - 1)
            draw_text_attr(r.y + 1, c, 2, term_attr(PAIR_MOTOR) | A_BOLD, arrow);
    }
    if (sel->focus != FOCUS_CHAIN)
        return;
    char line[200];
    int i = select_mass(sel), j = select_spring(sel);
    if (i >= 0)
        snprintf(line, sizeof line, " mass %d: m %.3g kg, c %.3g N·s/m │ Enter m  c damping"
                 "  ←→ move (paused)  ↑↓ next  Tab back ", i + 1, m->m[i], m->c[i]);
    else {
        char name[48];
        app_spring_name(m, j, name, sizeof name);
        char k3[40] = "", cs[40] = "";
        if (m->k3[j] != 0.0)
            snprintf(k3, sizeof k3, ", k3 %.3g N/m³", m->k3[j]);
        if (m->cs[j] != 0.0)
            snprintf(cs, sizeof cs, ", c %.3g N·s/m", m->cs[j]);
        snprintf(line, sizeof line, " %s: k %.3g N/m%s%s │ Enter k  c damper  K k3  ↑↓ next  "
                 "Tab back ", name, m->k[j], cs, k3);
    }
    draw_text_attr(r.y + r.h - 1, r.x + 2, r.w - 4, term_attr(PAIR_TITLE), line);
}
