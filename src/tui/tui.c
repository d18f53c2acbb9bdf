/* tui.c: the terminal front end: set-up and restore, colours, layout, drawing of the
 * scene, plots, controls and overlays, input, and the paced main loop.
 * Drawing goes to stdscr with erase() (never clear()) and one doupdate() per frame;
 * ncurses sends only what changed. */
#include "tui.h"

#include <locale.h>
#include <langinfo.h>
#include <math.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include <curses.h>

#include "../core/modes.h"
#include "../core/preset.h"
#include "input.h"
#include "tui_internal.h"

#define MIN_COLS 60
#define MIN_ROWS 20
#define PLOT_HZ 10.0    /* plots, while running */
#define LOW_FRAME_HZ 10.0 /* low bandwidth: scene and status */
#define LOW_PLOT_HZ 0.5   /* low bandwidth: plots, every 2 s */
#define BACKLOG 8192      /* bytes waiting for the terminal that mean it cannot keep up */
#define SCENE_SPAN 13.0 /* metres shown: 0 .. L + the motor's largest stroke */

static volatile sig_atomic_t quit_signal; /* SIGINT, SIGTERM, SIGHUP received */
static bool curses_on;
static bool ascii_only; /* not a UTF-8 locale: plain ASCII text and lines */

static const char *const plot_titles[6] = {"Displacement (m)", "Velocity (m/s)",
                                           "Acceleration (m/s²)", "x–v", "x–a", "v–a"};
static const char *const plot_titles_ascii[6] = {"Displacement (m)", "Velocity (m/s)",
                                                 "Acceleration (m/s^2)", "x-v", "x-a", "v-a"};
static const char *const plot_short[6] = {"x (m)", "v (m/s)", "a (m/s²)", "x–v", "x–a", "v–a"};
static const char *const plot_short_ascii[6] = {"x (m)", "v (m/s)", "a (m/s^2)", "x-v", "x-a",
                                                "v-a"};

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ---- terminal set-up and restore ---- */

static void restore_terminal(void)
{
    if (curses_on) {
        curses_on = false;
        endwin();
    }
}

static void on_quit_signal(int sig)
{
    quit_signal = sig;
}

/* A crash: give the terminal back, then die of the same signal. */
static void on_fatal_signal(int sig)
{
    restore_terminal();
    signal(sig, SIG_DFL);
    raise(sig);
}

static void install_signals(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_quit_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    sigaction(SIGHUP, &sa, NULL);
    sa.sa_handler = on_fatal_signal;
    sa.sa_flags = SA_RESETHAND;
    sigaction(SIGSEGV, &sa, NULL);
    sigaction(SIGBUS, &sa, NULL);
    sigaction(SIGFPE, &sa, NULL);
    sigaction(SIGILL, &sa, NULL);
    sigaction(SIGABRT, &sa, NULL);
}

/* 256-colour, 8-colour and mono palettes for the masses (blue, green, orange, red,
 * purple, then cyan, yellow, pink, brown, grey), the motor's pink and the rest. */
static void init_colors(struct tui *t)
{
    const char *no_color = getenv("NO_COLOR");
    t->color = has_colors() && !(no_color && *no_color);
    if (!t->color)
        return;
    start_color();
    use_default_colors();
    static const short c256[10] = {33, 40, 208, 196, 129, 44, 220, 205, 130, 250};
    static const short c8[10] = {COLOR_BLUE,    COLOR_GREEN, COLOR_YELLOW, COLOR_RED,
                                 COLOR_MAGENTA, COLOR_CYAN,  COLOR_YELLOW, COLOR_MAGENTA,
                                 COLOR_RED,     COLOR_WHITE};
    bool rich = COLORS >= 256;
    for (int i = 0; i < 10; i++)
        init_pair((short)(PAIR_MASS + i), rich ? c256[i] : c8[i], -1);
    init_pair(PAIR_MOTOR, rich ? 205 : COLOR_MAGENTA, -1);
    init_pair(PAIR_SPRING, rich ? 34 : COLOR_GREEN, -1);
    init_pair(PAIR_DIM, rich ? 240 : COLOR_WHITE, -1);
    init_pair(PAIR_TITLE, rich ? 45 : COLOR_CYAN, -1);
    init_pair(PAIR_WARN, rich ? 214 : COLOR_YELLOW, -1);
    init_pair(PAIR_WALL, rich ? 244 : COLOR_WHITE, -1);
    init_pair(PAIR_SELECT, COLOR_BLACK, rich ? 45 : COLOR_CYAN);
}

/* Attribute for colour pair p (or a mono stand-in). */
attr_t tui_pair_attr(const struct tui *t, int p)
{
    if (t->color)
        return COLOR_PAIR(p);
    if (p == PAIR_DIM || p == PAIR_WALL)
        return A_DIM;
    if (p == PAIR_WARN || p == PAIR_TITLE)
        return A_BOLD;
    if (p == PAIR_SELECT)
        return A_REVERSE;
    return A_NORMAL;
}

attr_t tui_mass_attr(const struct tui *t, int i)
{
    return tui_pair_attr(t, PAIR_MASS + i % 10);
}

/* ---- small drawing helpers ---- */

/* Writes UTF-8 or ASCII text s at (y, x), at most w columns. */
void tui_put(int y, int x, int w, const char *s)
{
    if (w <= 0 || y < 0 || x < 0)
        return;
    mvaddnstr(y, x, s, -1);
    (void)w;
}

/* Columns text s takes (UTF-8 characters, each one column here). */
int tui_text_width(const char *s)
{
    int n = 0;
    for (; *s; s++)
        n += (*s & 0xC0) != 0x80;
    return n;
}

/* Writes at most w columns of text s (counting UTF-8 characters as one column). */
void tui_putn(int y, int x, int w, const char *s)
{
    char plain[512];
    if (w <= 0)
        return;
    if (ascii_only) {
        /* The few non-ASCII characters in our own text, spelled in ASCII. */
        size_t o = 0;
        for (const char *p = s; *p && o < sizeof plain - 3; p++) {
            static const char *const fancy[][2] = {{"◆", "*"}, {"■", "#"}, {"┃", "|"},
                                                   {"┊", ":"}, {"━", "-"}, {"–", "-"},
                                                   {"│", "|"}, {"▸", ">"}, {"×", "x"}};
            size_t f = 0;
            while (f < sizeof fancy / sizeof *fancy && strncmp(p, fancy[f][0], strlen(fancy[f][0])))
                f++;
            if (f < sizeof fancy / sizeof *fancy) {
                plain[o++] = fancy[f][1][0];
                p += strlen(fancy[f][0]) - 1;
            } else if (strncmp(p, "·", 2) == 0) {
                plain[o++] = ' ';
                p++;
            } else if (strncmp(p, "²", 2) == 0) {
                plain[o++] = '^';
                plain[o++] = '2';
                p++;
            } else if ((unsigned char)*p >= 0x80) {
                if ((*p & 0xC0) != 0x80)
                    plain[o++] = '?';
            } else {
                plain[o++] = *p;
            }
        }
        plain[o] = '\0';
        s = plain;
    }
    int cols = 0;
    const char *p = s;
    while (*p && cols < w) {
        p++;
        while ((*p & 0xC0) == 0x80)
            p++;
        cols++;
    }
    mvaddnstr(y, x, s, (int)(p - s));
}

void tui_printf(int y, int x, int w, const char *fmt, ...)
{
    char buf[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    tui_putn(y, x, w, buf);
}

chtype tui_line(enum line l)
{
    if (ascii_only)
        return (chtype)"-|+++++" "+"[l];
    switch (l) {
    case L_H:
        return ACS_HLINE;
    case L_V:
        return ACS_VLINE;
    case L_UL:
        return ACS_ULCORNER;
    case L_UR:
        return ACS_URCORNER;
    case L_LL:
        return ACS_LLCORNER;
    case L_LR:
        return ACS_LRCORNER;
    case L_RTEE:
        return ACS_RTEE;
    case L_TTEE:
        return ACS_TTEE;
    }
    return '+';
}

/* A box with an optional title near the left (centre = false) or centred. */
void tui_frame(const struct tui *t, struct rect r, const char *title, bool centre)
{
    if (r.h < 2 || r.w < 2)
        return;
    mvaddch(r.y, r.x, tui_line(L_UL));
    mvhline(r.y, r.x + 1, tui_line(L_H), r.w - 2);
    mvaddch(r.y, r.x + r.w - 1, tui_line(L_UR));
    mvvline(r.y + 1, r.x, tui_line(L_V), r.h - 2);
    mvvline(r.y + 1, r.x + r.w - 1, tui_line(L_V), r.h - 2);
    mvaddch(r.y + r.h - 1, r.x, tui_line(L_LL));
    mvhline(r.y + r.h - 1, r.x + 1, tui_line(L_H), r.w - 2);
    mvaddch(r.y + r.h - 1, r.x + r.w - 1, tui_line(L_LR));
    if (title && r.w > 6) {
        int len = (int)strlen(title);
        int max = r.w - 4;
        int shown = len;
        /* Count UTF-8 characters, not bytes, for centring. */
        int chars = 0;
        for (const char *p = title; *p; p++)
            chars += (*p & 0xC0) != 0x80;
        shown = chars < max ? chars : max;
        int x = centre ? r.x + (r.w - shown - 2) / 2 : r.x + 1;
        attron(tui_pair_attr(t, PAIR_TITLE) | A_BOLD);
        mvaddch(r.y, x, ' ');
        tui_putn(r.y, x + 1, shown, title);
        addch(' ');
        attroff(tui_pair_attr(t, PAIR_TITLE) | A_BOLD);
        (void)len;
    }
}

/* Draws a braille canvas at (y, x): each cell with dots in its colour. */
void tui_canvas(const struct tui *t, const struct canvas *c, int y, int x)
{
    for (int cy = 0; cy < c->rows; cy++) {
        for (int cx = 0; cx < c->cols; cx++) {
            uint8_t bits = canvas_bits(c, cx, cy);
            if (!bits)
                continue;
            int col = c->color[(size_t)cy * c->cols + cx];
            attr_t a = col >= PAIR_MASS && col < PAIR_MASS + 10 ? tui_mass_attr(t, col - PAIR_MASS)
                                                                 : tui_pair_attr(t, col);
            if (t->utf8) {
                /* The wide character itself: no multibyte decoding per cell. */
                wchar_t wc[2] = {(wchar_t)(0x2800 + bits), 0};
                cchar_t cc;
                setcchar(&cc, wc, a & ~A_COLOR, (short)PAIR_NUMBER(a), NULL);
                mvadd_wch(y + cy, x + cx, &cc);
            } else {
                mvaddch(y + cy, x + cx, (chtype)braille_ascii(bits) | a);
            }
        }
    }
}

/* ---- layout ---- */

static void layout(struct tui *t)
{
    getmaxyx(stdscr, t->rows, t->cols);
    t->too_small = t->cols < MIN_COLS || t->rows < MIN_ROWS;
    if (t->too_small)
        return;
    int ctrl_w = t->cols >= 110 ? 32 : 28;
    t->status = (struct rect){0, 0, 1, t->cols};
    t->hints = (struct rect){t->rows - 1, 0, 1, t->cols};
    t->scene = (struct rect){1, 0, 5, t->cols};
    int top = 6, h = t->rows - 7, w = t->cols - ctrl_w;
    t->controls = (struct rect){top, w, h, ctrl_w};
    int pw = w / 3, ph = h / 2;
    for (int i = 0; i < 6; i++) {
        struct plotview *p = &t->plots[i];
        int col = i % 3, row = i / 3;
        p->r = (struct rect){top + row * ph, col * pw, row ? h - ph : ph,
                             col == 2 ? w - 2 * pw : pw};
        canvas_free(p->canvas);
        p->xs.set = p->ys.set = false; /* tick counts depend on the size: scale afresh */
        /* Inside the frame: y labels take 6 columns, the x axis and its labels 2 rows. */
        int cw = p->r.w - 2 - 6, chh = p->r.h - 2 - 2;
        p->canvas = canvas_new(cw < 1 ? 1 : cw, chh < 1 ? 1 : chh);
    }
    t->area = (struct rect){top, 0, h, w};
    canvas_free(t->view_canvas);
    t->view_canvas = canvas_new(w - 2 - 7, h - 2 - 2);
    t->view_ys.set = false;
    canvas_free(t->scene_canvas);
    t->scene_canvas = canvas_new(t->scene.w - 2, 3);
    t->plots_dirty = true;
}

/* ---- the scene ---- */

/* Column (fractional) of physical position X (m). */
static double scene_col(const struct tui *t, double X)
{
    return t->scene_x0 + X * t->scene_cpm;
}

/* Elements the chain has: N+1 springs (N for a free end) and N masses. */
static int elements(const struct tui *t);

/* Keeps the chain selection on an element that exists (a preset or a new N may have
 * made the chain shorter). */
static void clamp_elem(struct tui *t)
{
    if (t->elem >= elements(t) || t->elem < 0)
        t->elem = 1;
}

int tui_selected_mass(const struct tui *t)
{
    return t->focus == FOCUS_CHAIN && t->elem % 2 == 1 ? t->elem / 2 : -1;
}

/* The selected spring, or -1. */
static int selected_spring(const struct tui *t)
{
    return t->focus == FOCUS_CHAIN && t->elem % 2 == 0 ? t->elem / 2 : -1;
}

static int elements(const struct tui *t)
{
    const struct model *m = t->app.model;
    return 2 * m->n + (m->boundary == BOUNDARY_FREE ? 0 : 1);
}

/* A zig-zag spring between physical positions a and b on the scene canvas. */
static void draw_spring(struct tui *t, double a, double b, uint8_t color)
{
    struct canvas *c = t->scene_canvas;
    int x0 = (int)lround(2.0 * (scene_col(t, a) - t->scene.x - 1));
    int x1 = (int)lround(2.0 * (scene_col(t, b) - t->scene.x - 1));
    int mid = 5, amp = 3; /* dot rows 2..8 of 12 */
    if (x1 - x0 < 6) {
        canvas_line(c, x0, mid, x1, mid, color);
        return;
    }
    const int zigs = 8;
    int px = x0, py = mid;
    for (int k = 1; k <= 2 * zigs + 1; k++) {
        int x = x0 + (int)lround((double)(x1 - x0) * k / (2 * zigs + 2));
        int y = mid + ((k % 2) ? -amp : amp);
        canvas_line(c, px, py, x, y, color);
        px = x, py = y;
    }
    canvas_line(c, px, py, x1, mid, color);
}

/* A block from physical a to b, height rows tall (up to 3, from the bottom), with
 * sub-cell edges: eighth blocks across, and lower eighths on a part-filled top row. */
static void draw_block(struct tui *t, double a, double b, double height, attr_t attr,
                       const char *label, bool selected)
{
    static const char *const left_eighths[9] = {" ", "▏", "▎", "▍", "▌", "▋", "▊", "▉", "█"};
    static const char *const lower_eighths[9] = {" ", "▁", "▂", "▃", "▄", "▅", "▆", "▇", "█"};
    double c0 = scene_col(t, a), c1 = scene_col(t, b);
    int first = (int)floor(c0), last = (int)ceil(c1) - 1;
    int xmin = t->scene.x + 1, xmax = t->scene.x + t->scene.w - 2;
    for (int row = 0; row < 3; row++) {
        int y = t->scene.y + 1 + row;
        double fill = height - (2 - row); /* of this row, from its bottom */
        if (fill <= 0.06)
            continue;
        for (int x = first; x <= last; x++) {
            if (x < xmin || x > xmax)
                continue;
            double lo = fmax(c0, x), hi = fmin(c1, x + 1.0);
            if (hi <= lo)
                continue;
            attron(attr);
            if (!t->utf8) {
                mvaddch(y, x, selected ? '@' : (row == 1 ? '=' : '#'));
            } else if (fill < 0.94) {
                mvaddstr(y, x, lower_eighths[(int)lround(fill * 8)]);
            } else if (hi - lo > 0.94) {
                mvaddstr(y, x, "█");
            } else if (lo - x < 0.06) {
                /* Covers the cell's left part: a left block of that many eighths. */
                mvaddstr(y, x, left_eighths[(int)lround((hi - lo) * 8)]);
            } else {
                /* Covers the right part: the uncovered left part, reversed. */
                int e = (int)lround((lo - x) * 8);
                attron(A_REVERSE);
                mvaddstr(y, x, e <= 0 ? " " : left_eighths[e > 8 ? 8 : e]);
                attroff(A_REVERSE);
            }
            attroff(attr);
        }
    }
    if (label) {
        int x = (int)floor(0.5 * (c0 + c1));
        if (x >= xmin && x <= xmax) {
            attron(attr | A_REVERSE | A_BOLD);
            if (selected)
                attron(A_UNDERLINE | A_BLINK);
            mvaddstr(t->scene.y + 3, x, label);
            attroff(attr | A_REVERSE | A_BOLD | A_UNDERLINE | A_BLINK);
        }
    }
}

static void draw_scene(struct tui *t)
{
    const struct app *app = &t->app;
    const struct model *m = app->model;
    const double *x = sim_x(app->sim);
    double w = model_block_width(m);
    struct rect r = t->scene;
    int inner = r.w - 2;
    int wall_w = 2, house_w = 9;
    t->scene_x0 = r.x + 1 + wall_w;
    t->scene_cpm = (double)(inner - wall_w - house_w) / SCENE_SPAN;
    char title[64];
    snprintf(title, sizeof title, "Chain  t = %.2f s", sim_time(app->sim));
    tui_frame(t, r, title, false);

    /* Left wall. */
    attron(tui_pair_attr(t, PAIR_WALL));
    for (int row = 1; row <= 3; row++)
        tui_put(r.y + row, r.x + 1, wall_w, t->utf8 ? "▓▓" : "##");
    attroff(tui_pair_attr(t, PAIR_WALL));

    /* Springs on a braille canvas (ASCII: a row of / and \). */
    double u = sim_end_position(app->sim);
    double end = MODEL_LENGTH + (m->boundary == BOUNDARY_MOTOR ? u : 0.0);
    canvas_clear(t->scene_canvas);
    for (int j = 0; j <= m->n; j++) {
        if (j == m->n && m->boundary == BOUNDARY_FREE)
            break;
        double a = j == 0 ? 0.0 : model_equilibrium(m, j - 1) + x[j - 1] + 0.5 * w;
        double b = j == m->n ? end : model_equilibrium(m, j) + x[j] - 0.5 * w;
        if (b <= a)
            continue;
        int sel = selected_spring(t) == j;
        if (t->utf8) {
            draw_spring(t, a, b, sel ? PAIR_TITLE : PAIR_SPRING);
        } else {
            int c0 = (int)lround(scene_col(t, a)), c1 = (int)lround(scene_col(t, b));
            attron(tui_pair_attr(t, sel ? PAIR_TITLE : PAIR_SPRING) | (sel ? A_BOLD : 0));
            for (int c = c0; c < c1; c++)
                if (c > r.x && c < r.x + r.w - 1)
                    mvaddch(r.y + 2, c, ((c - c0) % 2) ? '\\' : '/');
            attroff(tui_pair_attr(t, PAIR_TITLE) | tui_pair_attr(t, PAIR_SPRING) | A_BOLD);
        }
    }
    if (t->utf8) {
        /* The blank cells between the coils take the springs' colour too: a colour
         * change costs more bytes than the character, and most frames change these rows. */
        attron(tui_pair_attr(t, PAIR_SPRING));
        for (int row = 1; row <= 3; row++)
            mvhline(r.y + row, r.x + 3, ' ', r.w - 4);
        attroff(tui_pair_attr(t, PAIR_SPRING));
        tui_canvas(t, t->scene_canvas, r.y + 1, r.x + 1);
    }

    /* Right end: piston and motor housing, or a wall. */
    int hx = r.x + r.w - 1 - house_w;
    if (m->boundary == BOUNDARY_MOTOR) {
        double face = scene_col(t, end);
        attron(tui_pair_attr(t, PAIR_WALL));
        for (int c = (int)ceil(face); c < hx; c++)
            mvaddstr(r.y + 2, c, t->utf8 ? "═" : "=");
        attroff(tui_pair_attr(t, PAIR_WALL));
        draw_block(t, end, end + 0.12, 3.0, tui_pair_attr(t, PAIR_WALL), NULL, false);
        attron(tui_pair_attr(t, PAIR_WALL));
        tui_put(r.y + 1, hx, house_w, t->utf8 ? "┌───────┐" : "+-------+");
        tui_put(r.y + 2, hx, house_w, t->utf8 ? "┤MOTOR  │" : "|MOTOR  |");
        tui_put(r.y + 3, hx, house_w, t->utf8 ? "└───────┘" : "+-------+");
        attroff(tui_pair_attr(t, PAIR_WALL));
        attron(tui_pair_attr(t, PAIR_MOTOR) | A_BOLD);
        tui_put(r.y + 2, hx + 7, 1, t->utf8 ? "●" : "*");
        attroff(tui_pair_attr(t, PAIR_MOTOR) | A_BOLD);
    } else if (m->boundary == BOUNDARY_WALL) {
        int c = (int)lround(scene_col(t, MODEL_LENGTH));
        attron(tui_pair_attr(t, PAIR_WALL));
        for (int row = 1; row <= 3; row++)
            tui_put(r.y + row, c, 2, t->utf8 ? "▓▓" : "##");
        attroff(tui_pair_attr(t, PAIR_WALL));
    }

    /* Masses, drawn to scale, each with its number; heavier ones stand taller. */
    double mmax = 0.0;
    for (int i = 0; i < m->n; i++)
        mmax = fmax(mmax, m->m[i]);
    for (int i = 0; i < m->n; i++) {
        double X = model_equilibrium(m, i) + x[i];
        char label[4];
        snprintf(label, sizeof label, "%d", (i + 1) % 10);
        double height = fmax(1.0, 3.0 * sqrt(m->m[i] / mmax));
        draw_block(t, X - 0.5 * w, X + 0.5 * w, height, tui_mass_attr(t, i), label,
                   tui_selected_mass(t) == i);
    }
    if (t->focus == FOCUS_CHAIN) {
        char line[200];
        int i = tui_selected_mass(t), j = selected_spring(t);
        if (i >= 0)
            snprintf(line, sizeof line, " mass %d: m %.3g kg, c %.3g N·s/m │ Enter m  c damping"
                     "  ←→ move (paused)  ↑↓ next  Tab back ", i + 1, m->m[i], m->c[i]);
        else
            snprintf(line, sizeof line, " spring %d: k %.3g N/m │ Enter k  ↑↓ next  Tab back ",
                     j, m->k[j]);
        attron(tui_pair_attr(t, PAIR_TITLE));
        tui_putn(r.y + r.h - 1, r.x + 2, r.w - 4, line);
        attroff(tui_pair_attr(t, PAIR_TITLE));
    }
}

/* ---- plots ---- */

/* Value of quantity q (1 x, 2 v, 3 a) of mass i in record rec. */
static double quantity(const struct trail *tr, const double *rec, int q, int i)
{
    switch (q) {
    case 1:
        return rec[TRAIL_X(tr, i)];
    case 2:
        return rec[TRAIL_V(tr, i)];
    default:
        return rec[TRAIL_A(tr, i)];
    }
}

/* Draws plot p; with refresh, first takes the newest samples (scales and dots),
 * otherwise draws what the last refresh took, so a frame between refreshes sends
 * nothing new to the terminal. */
static void draw_plot(struct tui *t, struct plotview *p, double t_now, bool refresh)
{
    const struct trail *tr = t->app.trail;
    const struct model *m = t->app.model;
    struct rect r = p->r;
    struct canvas *c = p->canvas;
    int idx = (int)(p - t->plots);
    bool narrow = r.w - 4 < (int)strlen(plot_titles_ascii[idx]) + 2;
    tui_frame(t, r, narrow ? (t->utf8 ? plot_short[idx] : plot_short_ascii[idx])
                       : (t->utf8 ? plot_titles[idx] : plot_titles_ascii[idx]), true);
    if (r.w < 12 || r.h < 6)
        return;
    double t0 = t_now - APP_WINDOW;
    bool motor = idx == 0 && m->boundary == BOUNDARY_MOTOR;
    int yticks = c->rows >= 8 ? 4 : 2, xticks = c->cols >= 30 ? 4 : 2;
    /* Only a refresh looks at the samples: the ones inside the window, and their range
     * for the autoscale. Frames in between draw the dots the last refresh left. */
    const double *rec = NULL;
    int k = 0;
    if (refresh) {
        const double *first = trail_first(tr);
        int start = 0;
        while (start < tr->count && first[(size_t)start * tr->width + TRAIL_T] < t0)
            start++;
        rec = first + (size_t)start * tr->width;
        k = tr->count - start;
        double ymin = INFINITY, ymax = -INFINITY, xmin = INFINITY, xmax = -INFINITY;
        for (int s = 0; s < k; s++) {
            const double *q = rec + (size_t)s * tr->width;
            for (int i = 0; i < m->n; i++) {
                double yv = quantity(tr, q, p->yq, i);
                ymin = fmin(ymin, yv), ymax = fmax(ymax, yv);
                if (p->xq) {
                    double xv = quantity(tr, q, p->xq, i);
                    xmin = fmin(xmin, xv), xmax = fmax(xmax, xv);
                }
            }
            if (motor)
                ymin = fmin(ymin, q[TRAIL_U]), ymax = fmax(ymax, q[TRAIL_U]);
        }
        if (k > 0) {
            plot_scale_update(&p->ys, ymin, ymax, yticks, 30);
            if (p->xq)
                plot_scale_update(&p->xs, xmin, xmax, xticks, 30);
        }
    }
    if (!p->ys.set)
        plot_scale_update(&p->ys, -1.0, 1.0, yticks, 30);
    if (p->xq && !p->xs.set)
        plot_scale_update(&p->xs, -1.0, 1.0, xticks, 30);

    int cx = r.x + 1 + 6, cy = r.y + 1; /* canvas origin */
    /* Grid: dim dots on the tick rows, and the y labels. */
    attron(tui_pair_attr(t, PAIR_DIM));
    for (double v = p->ys.lo; v <= p->ys.hi + 1e-9 * p->ys.step; v += p->ys.step) {
        double f = (v - p->ys.lo) / (p->ys.hi - p->ys.lo);
        int row = (int)lround((1.0 - f) * (c->rows * 4 - 1)) / 4;
        for (int col = 0; col < c->cols; col += 2)
            mvaddstr(cy + row, cx + col, t->utf8 ? "·" : ".");
    }
    attroff(tui_pair_attr(t, PAIR_DIM));
    for (double v = p->ys.lo; v <= p->ys.hi + 1e-9 * p->ys.step; v += p->ys.step) {
        double f = (v - p->ys.lo) / (p->ys.hi - p->ys.lo);
        int row = (int)lround((1.0 - f) * (c->rows * 4 - 1)) / 4;
        char lab[16];
        plot_tick_label(v, p->ys.step, lab, sizeof lab);
        tui_printf(cy + row, r.x + 1, 6, "%5.5s", lab);
        mvaddch(cy + row, r.x + 6, tui_line(L_RTEE));
    }
    for (int row = 0; row < c->rows; row++)
        if (mvinch(cy + row, r.x + 6) == ' ')
            mvaddch(cy + row, r.x + 6, tui_line(L_V));
    /* x axis and its labels. */
    int ay = cy + c->rows;
    mvaddch(ay, r.x + 6, tui_line(L_LL));
    mvhline(ay, cx, tui_line(L_H), c->cols);
    double xlo = p->xq ? p->xs.lo : -APP_WINDOW, xhi = p->xq ? p->xs.hi : 0.0;
    double xstep = p->xq ? p->xs.step : plot_tick_step(-APP_WINDOW, 0.0, xticks);
    int free_from = r.x + 1; /* first column a label may use: labels never touch */
    if (!p->xq) {
        tui_put(ay + 1, r.x + 2, 1, "s");
        free_from = r.x + 4;
    }
    for (double v = xlo; v <= xhi + 1e-9 * xstep; v += xstep) {
        int col = (int)lround((v - xlo) / (xhi - xlo) * (c->cols - 1));
        char lab[16];
        plot_tick_label(v, xstep, lab, sizeof lab);
        mvaddch(ay, cx + col, tui_line(L_TTEE));
        int len = (int)strlen(lab);
        int lx = cx + col - len / 2;
        if (lx + len > r.x + r.w - 1)
            lx = r.x + r.w - 1 - len;
        if (lx < free_from)
            continue;
        tui_put(ay + 1, lx, len, lab);
        free_from = lx + len + 1;
    }

    /* The data. */
    if (refresh)
        canvas_clear(c);
    for (int i = refresh ? m->n - 1 : -1; i >= 0; i--) {
        unsigned char col = (unsigned char)(PAIR_MASS + i % 10);
        if (p->xq == 0) {
            int off = p->yq == 1 ? TRAIL_X(tr, i) : p->yq == 2 ? TRAIL_V(tr, i) : TRAIL_A(tr, i);
            plot_series(c, rec + TRAIL_T, rec + off, k, (size_t)tr->width, t0, t_now, &p->ys,
                        false, col);
        } else {
            int xo = p->xq == 1 ? TRAIL_X(tr, i) : TRAIL_V(tr, i);
            int yo = p->yq == 2 ? TRAIL_V(tr, i) : TRAIL_A(tr, i);
            plot_curve(c, rec + xo, rec + yo, k, (size_t)tr->width, &p->xs, &p->ys, col);
        }
    }
    if (motor && refresh)
        plot_series(c, rec + TRAIL_T, rec + TRAIL_U, k, (size_t)tr->width, t0, t_now, &p->ys,
                    true, PAIR_MOTOR);
    tui_canvas(t, c, cy, cx);

    /* Legend on the bottom border: mass numbers in their colours, and the motor. */
    int lx = r.x + 2, ly = r.y + r.h - 1;
    for (int i = 0; i < m->n && lx < r.x + r.w - 4; i++) {
        attron(tui_mass_attr(t, i) | A_BOLD);
        tui_printf(ly, lx, 3, t->utf8 ? "━%d" : "-%d", i + 1);
        attroff(tui_mass_attr(t, i) | A_BOLD);
        lx += (i + 1 >= 10) ? 4 : 3;
    }
    if (motor && lx + 7 < r.x + r.w - 1) {
        attron(tui_pair_attr(t, PAIR_MOTOR));
        tui_putn(ly, lx, 7, t->utf8 ? "┅motor" : ":motor");
        attroff(tui_pair_attr(t, PAIR_MOTOR));
    }
}

/* ---- controls, status, hints, overlays ---- */

static void draw_controls(struct tui *t)
{
    struct rect r = t->controls;
    tui_frame(t, r, "Controls", false);
    for (int i = 0; i < CTL_COUNT && i < r.h - 2; i++) {
        char value[96];
        app_control_value(&t->app, (enum control)i, value, sizeof value);
        bool sel = t->focus == FOCUS_CONTROLS && t->control == i;
        if (sel)
            attron(tui_pair_attr(t, PAIR_SELECT));
        char line[160];
        snprintf(line, sizeof line, "%s%-10s %s", sel ? (t->utf8 ? "▸" : ">") : " ",
                 app_control_label((enum control)i), value);
        mvhline(r.y + 1 + i, r.x + 1, ' ', r.w - 2);
        tui_putn(r.y + 1 + i, r.x + 1, r.w - 2, line);
        if (sel)
            attroff(tui_pair_attr(t, PAIR_SELECT));
    }
    /* The frequency range with the natural frequencies marked and the drive on it. */
    int y = r.y + 1 + CTL_COUNT;
    if (y < r.y + r.h - 1 && t->app.modes_ok) {
        const struct model *m = t->app.model;
        int x0 = r.x + 5, w = r.w - 11;
        tui_put(y, r.x + 1, 3, "0.1");
        mvhline(y, x0, tui_line(L_H), w);
        tui_put(y, x0 + w + 1, 3, "5Hz");
        attron(tui_pair_attr(t, PAIR_TITLE));
        for (int j = 0; j < m->n; j++) {
            double f = t->app.modes[j];
            if (f >= APP_FMIN && f <= APP_FMAX)
                mvaddch(y, x0 + (int)lround(app_freq_fraction(f) * (w - 1)),
                        ascii_only ? '|' : ACS_PLUS);
        }
        attroff(tui_pair_attr(t, PAIR_TITLE));
        attron(tui_pair_attr(t, PAIR_MOTOR) | A_BOLD);
        double f = m->motor.frequency;
        if (f >= APP_FMIN && f <= APP_FMAX)
            tui_put(y, x0 + (int)lround(app_freq_fraction(f) * (w - 1)), 1,
                    ascii_only ? "o" : "●");
        attroff(tui_pair_attr(t, PAIR_MOTOR) | A_BOLD);
    }
    /* Natural frequencies under the controls, so resonance is checked, not guessed. */
    y = r.y + 1 + CTL_COUNT + 1;
    if (y < r.y + r.h - 1) {
        const struct model *m = t->app.model;
        const double *f = t->app.modes; /* kept up to date by the app on every change */
        if (t->app.modes_ok) {
            attron(tui_pair_attr(t, PAIR_DIM));
            tui_putn(y, r.x + 1, r.w - 2, " natural frequencies (Hz)");
            int x = r.x + 2;
            y++;
            for (int j = 0; j < m->n && y < r.y + r.h - 1; j++) {
                char num[16];
                snprintf(num, sizeof num, "%.3f", f[j]);
                if (x + (int)strlen(num) > r.x + r.w - 2)
                    x = r.x + 2, y++;
                if (y >= r.y + r.h - 1)
                    break;
                tui_put(y, x, (int)strlen(num), num);
                x += (int)strlen(num) + 1;
            }
            attroff(tui_pair_attr(t, PAIR_DIM));
        }
    }
}

static void draw_status(struct tui *t)
{
    const struct app *app = &t->app;
    const struct model *m = app->model;
    char motor[64];
    if (m->boundary == BOUNDARY_MOTOR)
        snprintf(motor, sizeof motor, "motor %s %.2f Hz %.2f m", motor_wave_name(m->motor.wave),
                 m->motor.frequency, m->motor.amplitude);
    else
        snprintf(motor, sizeof motor, "%s end", model_boundary_name(m->boundary));
    const char *bar = t->utf8 ? "│" : "|";
    char line[400], speed[64] = "";
    if (app->speed != 1.0 || t->behind || app->cfg.low_bandwidth)
        snprintf(speed, sizeof speed, " %s %gx%s%s", bar, app->speed, t->behind ? " behind" : "",
                 app->cfg.low_bandwidth ? " low-bw" : "");
    /* The full line where it fits; the SPEC's essentials where it does not. */
    snprintf(line, sizeof line, " springsim %s %-7s t = %.2f s %s %s %s N %d %s dt %.3f s %s "
             "history %d%s", t->utf8 ? "▸" : ">", app->running ? "Running" : "Paused",
             sim_time(app->sim), bar, motor, bar, m->n, bar, app->cfg.dt, bar,
             history_count(app->hist), speed);
    if (tui_text_width(line) > t->cols) {
        if (m->boundary == BOUNDARY_MOTOR)
            snprintf(motor, sizeof motor, "motor %s %.2f Hz", motor_wave_name(m->motor.wave),
                     m->motor.frequency);
        snprintf(line, sizeof line, " %s  t = %.2f s %s %s %s history %d%s",
                 app->running ? "Running" : "Paused", sim_time(app->sim), bar, motor, bar,
                 history_count(app->hist), speed);
    }
    attron(A_REVERSE);
    mvhline(0, 0, ' ', t->cols);
    tui_putn(0, 0, t->cols, line);
    const char *right = "? help  q quit ";
    if (tui_text_width(line) + 17 < t->cols)
        tui_put(0, t->cols - (int)strlen(right), (int)strlen(right), right);
    attroff(A_REVERSE);
}

static void edit_prompt(const struct tui *t, char *buf, size_t len);

static void draw_hints(struct tui *t)
{
    int y = t->hints.y;
    if (t->overlay == OVERLAY_EDIT) {
        char prompt[80];
        edit_prompt(t, prompt, sizeof prompt);
        attron(A_BOLD);
        tui_printf(y, 0, t->cols, " %s %s", prompt, t->edit);
        attroff(A_BOLD);
        printw("_   (Enter sets it, Esc cancels)");
        return;
    }
    if (t->overlay == OVERLAY_CONFIRM) {
        attron(tui_pair_attr(t, PAIR_WARN) | A_BOLD);
        tui_printf(y, 0, t->cols, " preset %s exists: replace it? (y/n)", t->save_name);
        attroff(tui_pair_attr(t, PAIR_WARN) | A_BOLD);
        return;
    }
    if (t->app.message[0]) {
        attron(t->app.message_is_error ? tui_pair_attr(t, PAIR_WARN) | A_BOLD : A_BOLD);
        tui_printf(y, 0, t->cols, " %s", t->app.message);
        attroff(tui_pair_attr(t, PAIR_WARN) | A_BOLD);
        return;
    }
    attron(tui_pair_attr(t, PAIR_DIM));
    tui_putn(y, 0, t->cols, t->utf8 ? " space start  . step  , back  r reset  R random  p presets  "
                                  "←→ adjust  ↑↓ select  Enter type  Tab masses  ? help"
                                : " space start  . step  , back  r reset  R random  p presets  "
                                  "<> adjust  ^v select  Enter type  Tab masses  ? help");
    attroff(tui_pair_attr(t, PAIR_DIM));
}

/* A centred box of h x w, cleared, with a title; returns its rectangle. */
static struct rect overlay_box(struct tui *t, int h, int w, const char *title)
{
    if (h > t->rows - 2)
        h = t->rows - 2;
    if (w > t->cols - 2)
        w = t->cols - 2;
    struct rect r = {(t->rows - h) / 2, (t->cols - w) / 2, h, w};
    for (int y = r.y; y < r.y + r.h; y++)
        mvhline(y, r.x, ' ', r.w);
    tui_frame(t, r, title, true);
    return r;
}

static void draw_help(struct tui *t)
{
    int lines = 0;
    for (const struct binding *b = input_bindings; b->name; b++)
        lines += b->help != NULL;
    /* Keys first; the notes on the mouse and typing only where there is room. */
    struct rect r = overlay_box(t, lines + 6, 78, "Keys");
    int y = r.y + 1;
    for (const struct binding *b = input_bindings; b->name && y < r.y + r.h - 1; b++) {
        if (!b->help)
            continue;
        char keys[64];
        snprintf(keys, sizeof keys, "%s", t->utf8 ? b->name : b->ascii);
        for (const struct binding *o = b + 1; o->name && !o->help; o++) {
            const char *nm = t->utf8 ? o->name : o->ascii;
            if (o->action == b->action && strcmp(nm, t->utf8 ? b->name : b->ascii) != 0 &&
                !strstr(keys, nm))
                snprintf(keys + strlen(keys), sizeof keys - strlen(keys), " %s", nm);
        }
        attron(A_BOLD);
        tui_putn(y, r.x + 2, 17, keys);
        attroff(A_BOLD);
        tui_putn(y, r.x + 19, r.w - 21, b->help);
        y++;
    }
    static const char *const notes[] = {
        "Mouse: click a control to select it, wheel to adjust it;",
        "drag a mass (paused) to set its initial position.",
        "Values can be typed: select a control and press Enter.",
    };
    for (int i = 0; i < 3 && y + 1 < r.y + r.h - 1; i++)
        tui_putn(++y, r.x + 2, r.w - 4, notes[i]);
}

static void draw_presets(struct tui *t)
{
    int n = t->npresets;
    struct rect r = overlay_box(t, (n ? n : 1) + 4, 76, "Presets");
    if (n == 0) {
        tui_putn(r.y + 1, r.x + 2, r.w - 4, "No presets found on the search path.");
        return;
    }
    int rows = r.h - 4, first = t->preset_sel >= rows ? t->preset_sel - rows + 1 : 0;
    for (int i = first; i < n && i - first < rows; i++) {
        bool sel = i == t->preset_sel;
        if (sel)
            attron(tui_pair_attr(t, PAIR_SELECT));
        mvhline(r.y + 1 + i - first, r.x + 1, ' ', r.w - 2);
        tui_printf(r.y + 1 + i - first, r.x + 2, r.w - 4, "%-15s %s", t->presets[i].name,
                t->presets[i].description);
        if (sel)
            attroff(tui_pair_attr(t, PAIR_SELECT));
    }
    attron(tui_pair_attr(t, PAIR_DIM));
    tui_putn(r.y + r.h - 2, r.x + 2, r.w - 4, "↑↓ choose   Enter load   Esc close");
    attroff(tui_pair_attr(t, PAIR_DIM));
}

/* Draws a frame; returns the seconds it took to hand it to the terminal. */
static double draw(struct tui *t, bool plots)
{
    clamp_elem(t);
    erase();
    if (t->too_small) {
        char msg[2][64];
        snprintf(msg[0], sizeof msg[0], "Terminal too small");
        snprintf(msg[1], sizeof msg[1], "need %dx%d, have %dx%d", MIN_COLS, MIN_ROWS, t->cols,
                 t->rows);
        for (int i = 0; i < 2; i++) {
            int len = (int)strlen(msg[i]);
            if (len > t->cols)
                len = t->cols;
            int y = t->rows / 2 - 1 + i;
            if (y >= 0 && y < t->rows)
                mvaddnstr(y, (t->cols - len) / 2, msg[i], len);
        }
        wnoutrefresh(stdscr);
        doupdate();
        return 0.0;
    }
    draw_status(t);
    draw_scene(t);
    double t_now = sim_time(t->app.sim);
    if (t->view == VIEW_PLOTS)
        for (int i = 0; i < 6; i++)
            draw_plot(t, &t->plots[i], t_now, plots);
    else
        views_draw(t, plots);
    draw_controls(t);
    draw_hints(t);
    if (t->overlay == OVERLAY_HELP)
        draw_help(t);
    else if (t->overlay == OVERLAY_PRESETS)
        draw_presets(t);
    wnoutrefresh(stdscr);
    double start = now_s();
    doupdate();
    return now_s() - start;
}

/* ---- input ---- */

static void open_presets(struct tui *t)
{
    free(t->presets);
    t->npresets = preset_scan(t->app.exe_dir, &t->presets);
    t->preset_sel = 0;
    for (int i = 0; i < t->npresets; i++)
        if (strcmp(t->presets[i].name, t->app.preset) == 0)
            t->preset_sel = i;
    t->overlay = OVERLAY_PRESETS;
}

static void start_edit(struct tui *t, enum edit_target target)
{
    t->overlay = OVERLAY_EDIT;
    t->edit_target = target;
    t->edit[0] = '\0';
    t->edit_len = 0;
}

/* What the prompt says for the text being typed. */
static void edit_prompt(const struct tui *t, char *buf, size_t len)
{
    int i = t->elem / 2;
    switch (t->edit_target) {
    case EDIT_CONTROL:
        snprintf(buf, len, "%s =", app_control_label((enum control)t->control));
        break;
    case EDIT_MASS:
        snprintf(buf, len, "mass %d: m (kg) =", i + 1);
        break;
    case EDIT_DAMPING:
        snprintf(buf, len, "mass %d: c (N·s/m) =", i + 1);
        break;
    case EDIT_SPRING:
        snprintf(buf, len, "spring %d: k (N/m) =", i);
        break;
    case EDIT_SAVE:
        snprintf(buf, len, "save preset as:");
        break;
    }
}

/* Acts on the text typed, by what it was for. */
static void finish_edit(struct tui *t)
{
    struct app *app = &t->app;
    int i = t->elem / 2;
    switch (t->edit_target) {
    case EDIT_CONTROL:
        if (t->edit_len && app_set_text(app, (enum control)t->control, t->edit))
            app_say(app, false, "%s set", app_control_label((enum control)t->control));
        break;
    case EDIT_MASS:
        if (app_set_element(app, 'm', i, t->edit))
            app_say(app, false, "mass %d: m = %g kg", i + 1, app->model->m[i]);
        break;
    case EDIT_DAMPING:
        if (app_set_element(app, 'c', i, t->edit))
            app_say(app, false, "mass %d: c = %g N·s/m", i + 1, app->model->c[i]);
        break;
    case EDIT_SPRING:
        if (app_set_element(app, 'k', i, t->edit))
            app_say(app, false, "spring %d: k = %g N/m", i, app->model->k[i]);
        break;
    case EDIT_SAVE:
        if (app_save(app, t->edit, false) == SAVE_EXISTS) {
            snprintf(t->save_name, sizeof t->save_name, "%s", t->edit);
            t->overlay = OVERLAY_CONFIRM;
        }
        break;
    }
}

static void on_edit_key(struct tui *t, int ch)
{
    if (ch == 27) {
        t->overlay = OVERLAY_NONE;
    } else if (ch == '\n' || ch == '\r' || ch == KEY_ENTER) {
        t->overlay = OVERLAY_NONE;
        finish_edit(t);
    } else if (ch == KEY_BACKSPACE || ch == 127 || ch == 8) {
        if (t->edit_len)
            t->edit[--t->edit_len] = '\0';
    } else if (ch >= 32 && ch < 127 && t->edit_len < (int)sizeof t->edit - 1) {
        t->edit[t->edit_len++] = (char)ch;
        t->edit[t->edit_len] = '\0';
    }
}

static void on_preset_key(struct tui *t, enum action a)
{
    switch (a) {
    case ACT_UP:
        if (t->preset_sel > 0)
            t->preset_sel--;
        break;
    case ACT_DOWN:
        if (t->preset_sel < t->npresets - 1)
            t->preset_sel++;
        break;
    case ACT_ENTER:
        if (t->npresets)
            app_load_preset(&t->app, t->presets[t->preset_sel].path,
                            t->presets[t->preset_sel].name);
        t->overlay = OVERLAY_NONE;
        break;
    case ACT_ESCAPE:
    case ACT_PRESETS:
    case ACT_QUIT:
        t->overlay = OVERLAY_NONE;
        break;
    default:
        break;
    }
}

/* Steps of an adjustment: +-1, fine or coarse. */
static void adjust(struct tui *t, int dir, bool coarse)
{
    if (t->focus == FOCUS_CHAIN) {
        if (tui_selected_mass(t) >= 0)
            app_move_mass(&t->app, tui_selected_mass(t), dir * (coarse ? 0.5 : 0.05));
        else
            app_say(&t->app, false, "a spring is selected: ↑↓ to a mass to move it");
    } else
        app_adjust(&t->app, (enum control)t->control, dir, coarse);
}

static bool on_action(struct tui *t, enum action a)
{
    struct app *app = &t->app;
    if (a != ACT_NONE && a != ACT_REDRAW)
        app->message[0] = '\0';
    switch (a) {
    case ACT_QUIT:
        return false;
    case ACT_RUN:
        app->running = !app->running;
        break;
    case ACT_STEP:
        app->running = false;
        app_step(app);
        break;
    case ACT_BACK:
        app_back(app);
        break;
    case ACT_RESET:
        app_reset(app);
        app_say(app, false, "reset to t = 0");
        break;
    case ACT_RANDOM:
        app_random(app);
        break;
    case ACT_PRESETS:
        open_presets(t);
        break;
    case ACT_HELP:
        t->overlay = OVERLAY_HELP;
        break;
    case ACT_UP:
        if (t->focus == FOCUS_CHAIN)
            t->elem = (t->elem + elements(t) - 1) % elements(t);
        else
            t->control = (t->control + CTL_COUNT - 1) % CTL_COUNT;
        break;
    case ACT_DOWN:
        if (t->focus == FOCUS_CHAIN)
            t->elem = (t->elem + 1) % elements(t);
        else
            t->control = (t->control + 1) % CTL_COUNT;
        break;
    case ACT_LEFT:
        adjust(t, -1, false);
        break;
    case ACT_RIGHT:
        adjust(t, 1, false);
        break;
    case ACT_LEFT_BIG:
        adjust(t, -1, true);
        break;
    case ACT_RIGHT_BIG:
        adjust(t, 1, true);
        break;
    case ACT_ENTER:
        if (t->focus == FOCUS_CHAIN)
            start_edit(t, tui_selected_mass(t) >= 0 ? EDIT_MASS : EDIT_SPRING);
        else if (t->control == CTL_PRESET)
            open_presets(t);
        else if (t->control == CTL_MASSES && app->masses_pending != app->model->n)
            app_apply_masses(app);
        else
            start_edit(t, EDIT_CONTROL);
        break;
    case ACT_DAMPING:
        if (tui_selected_mass(t) >= 0)
            start_edit(t, EDIT_DAMPING);
        else
            app_say(app, false, "select a mass in the chain first (Tab, then ↑↓)");
        break;
    case ACT_FOCUS:
        t->focus = t->focus == FOCUS_CHAIN ? FOCUS_CONTROLS : FOCUS_CHAIN;
        if (t->elem >= elements(t) || t->elem % 2 == 0)
            t->elem = 1; /* mass 1 */
        break;
    case ACT_MODES:
    case ACT_RESPONSE:
    case ACT_ENERGY: {
        enum view v = a == ACT_MODES ? VIEW_MODES : a == ACT_RESPONSE ? VIEW_RESPONSE
                                                                      : VIEW_ENERGY;
        t->view = t->view == v ? VIEW_PLOTS : v;
        t->view_ys.set = false;
        break;
    }
    case ACT_NEAREST:
        app_nearest_mode(app);
        break;
    case ACT_SWEEP:
        app_toggle_sweep(app);
        if (app->sweep->active)
            t->view = VIEW_RESPONSE, t->view_ys.set = false;
        break;
    case ACT_SAVE:
        start_edit(t, EDIT_SAVE);
        break;
    case ACT_EXPORT: {
        char path[4200];
        app_export(app, NULL, path, sizeof path);
        break;
    }
    case ACT_SLOWER:
        app_adjust(app, CTL_SPEED, -1, false);
        break;
    case ACT_FASTER:
        app_adjust(app, CTL_SPEED, 1, false);
        break;
    case ACT_ESCAPE:
        t->focus = FOCUS_CONTROLS;
        break;
    case ACT_REDRAW:
        clearok(curscr, TRUE);
        break;
    case ACT_NONE:
        break;
    }
    t->plots_dirty = true;
    return true;
}

/* Mouse: click a control, wheel on it, drag a mass while paused. */
static void on_mouse(struct tui *t)
{
    MEVENT ev;
    if (getmouse(&ev) != OK)
        return;
    struct rect c = t->controls;
    bool in_controls = ev.x > c.x && ev.x < c.x + c.w - 1 && ev.y > c.y &&
                       ev.y <= c.y + CTL_COUNT;
    if (in_controls) {
        t->focus = FOCUS_CONTROLS;
        t->control = ev.y - c.y - 1;
        if (ev.bstate & BUTTON4_PRESSED)
            app_adjust(&t->app, (enum control)t->control, 1, false);
#ifdef BUTTON5_PRESSED
        else if (ev.bstate & BUTTON5_PRESSED)
            app_adjust(&t->app, (enum control)t->control, -1, false);
#endif
        t->plots_dirty = true;
        return;
    }
    struct rect s = t->scene;
    bool in_scene = ev.y > s.y && ev.y < s.y + s.h - 1;
    double X = (ev.x + 0.5 - t->scene_x0) / t->scene_cpm;
    if (in_scene && (ev.bstate & BUTTON1_PRESSED)) {
        const struct model *m = t->app.model;
        double w = model_block_width(m), best = 1e9;
        int pick = -1;
        for (int i = 0; i < m->n; i++) {
            double d = fabs(model_equilibrium(m, i) + sim_x(t->app.sim)[i] - X);
            if (d < best)
                best = d, pick = i;
        }
        t->focus = FOCUS_CHAIN;
        if (pick >= 0 && best < w + 1.0 / t->scene_cpm) {
            t->elem = 2 * pick + 1;
            t->dragging = !t->app.running;
            if (t->app.running)
                app_say(&t->app, false, "pause (space) to drag a mass");
        } else {
            /* Between masses: the spring there (spring j lies left of mass j+1). */
            int j = 0;
            while (j < m->n && model_equilibrium(m, j) + sim_x(t->app.sim)[j] < X)
                j++;
            if (2 * j < elements(t))
                t->elem = 2 * j;
        }
        return;
    }
    if (t->dragging && (ev.bstate & (REPORT_MOUSE_POSITION | BUTTON1_RELEASED))) {
        app_place_mass(&t->app, t->elem / 2, X);
        if (ev.bstate & BUTTON1_RELEASED)
            t->dragging = false;
        t->plots_dirty = true;
    }
}

static bool on_key(struct tui *t, int ch)
{
    if (ch == KEY_RESIZE) {
        layout(t);
        return true;
    }
    if (ch == KEY_MOUSE) {
        if (t->overlay == OVERLAY_NONE)
            on_mouse(t);
        return true;
    }
    if (t->overlay == OVERLAY_EDIT) {
        on_edit_key(t, ch);
        t->plots_dirty = true;
        return true;
    }
    if (t->overlay == OVERLAY_CONFIRM) {
        t->overlay = OVERLAY_NONE;
        if (ch == 'y' || ch == 'Y')
            app_save(&t->app, t->save_name, true);
        else
            app_say(&t->app, false, "not saved: %s kept as it was", t->save_name);
        return true;
    }
    enum action a = input_action(ch);
    if (t->overlay == OVERLAY_HELP) {
        if (a == ACT_HELP || a == ACT_ESCAPE || a == ACT_QUIT)
            t->overlay = OVERLAY_NONE;
        return true;
    }
    if (t->overlay == OVERLAY_PRESETS) {
        on_preset_key(t, a);
        t->plots_dirty = true;
        return true;
    }
    return on_action(t, a);
}

/* ---- main loop ---- */

/* Frames a second for the scene and the status line. */
static double frame_hz(const struct tui *t)
{
    double hz = t->app.cfg.fps;
    return t->app.cfg.low_bandwidth && hz > LOW_FRAME_HZ ? LOW_FRAME_HZ : hz;
}

/* After a frame that took `spent` seconds to hand to the terminal: if output keeps
 * piling up unread (a slow link: bytes queued, or writing blocked), step down to low
 * bandwidth on its own and say so. */
static void watch_backlog(struct tui *t, double spent)
{
    int queued = 0;
    if (t->app.cfg.low_bandwidth)
        return;
    if (ioctl(STDOUT_FILENO, TIOCOUTQ, &queued) != 0)
        queued = 0;
    bool slow = queued > BACKLOG || spent > 0.5 / frame_hz(t);
    t->backlog_frames = slow ? t->backlog_frames + 1 : 0;
    if (t->backlog_frames >= 3 || spent > 1.0) {
        t->app.cfg.low_bandwidth = true;
        t->backlog_frames = 0;
        app_say(&t->app, true, "the terminal is not keeping up: low bandwidth on (Bandwidth "
                "control turns it back)");
    }
}

/* Advances the simulation to follow the wall clock times the playback speed. */
static void advance(struct tui *t, double *debt, double elapsed)
{
    struct app *app = &t->app;
    if (!app->running) {
        *debt = 0.0;
        t->behind = false;
        return;
    }
    *debt += elapsed * app->speed;
    double dt = app->cfg.dt;
    double start = now_s();
    while (*debt >= dt && app->running) {
        if (!app_step(app))
            break;
        *debt -= dt;
        /* Never spend more than half a frame computing: fall behind and say so. */
        if (now_s() - start > 0.5 / frame_hz(t)) {
            t->behind = *debt > 2.0 * dt;
            if (*debt > 0.25 * app->speed)
                *debt = 0.0;
            return;
        }
    }
    t->behind = false;
}

int tui_run(const struct config *cfg, const char *exe_dir)
{
    static struct tui t;
    memset(&t, 0, sizeof t);
    if (app_init(&t.app, cfg, exe_dir) != 0) {
        fprintf(stderr, "springsim: out of memory\n");
        return EXIT_FAILURE;
    }
    t.utf8 = strcmp(nl_langinfo(CODESET), "UTF-8") == 0;
    ascii_only = !t.utf8;
    if (!isatty(STDIN_FILENO) || !isatty(STDOUT_FILENO)) {
        fprintf(stderr, "springsim: the interactive program needs a terminal; use --headless, "
                        "--modes or --sweep for scripts\n");
        app_free(&t.app);
        return EXIT_FAILURE;
    }
    if (!newterm(NULL, stdout, stdin)) {
        fprintf(stderr, "springsim: cannot use this terminal (TERM=%s)\n",
                getenv("TERM") ? getenv("TERM") : "unset");
        app_free(&t.app);
        return EXIT_FAILURE;
    }
    curses_on = true;
    atexit(restore_terminal);
    install_signals();
    cbreak();
    noecho();
    nonl();
    keypad(stdscr, TRUE);
    curs_set(0);
    set_escdelay(25);
    mousemask(BUTTON1_PRESSED | BUTTON1_RELEASED | BUTTON4_PRESSED | REPORT_MOUSE_POSITION
#ifdef BUTTON5_PRESSED
                  | BUTTON5_PRESSED
#endif
              ,
              NULL);
    mouseinterval(0);
    init_colors(&t);
    for (int i = 0; i < 6; i++) {
        t.plots[i].xq = i < 3 ? 0 : (i == 5 ? 2 : 1);
        t.plots[i].yq = i < 3 ? i + 1 : (i == 3 ? 2 : 3);
        t.plots[i].title = plot_titles[i];
    }
    layout(&t);
    if (t.app.message[0] == '\0')
        app_say(&t.app, false, "space starts; ? lists every key");

    double last = now_s(), debt = 0.0, next_frame = last;
    bool go = true;
    while (go && !quit_signal) {
        double now = now_s();
        advance(&t, &debt, now - last);
        last = now;
        /* Plots refresh at PLOT_HZ while running, at once after anything else. */
        bool plots = t.plots_dirty || (t.app.running && now >= t.plot_due);
        if (plots) {
            t.plot_due = now + 1.0 / (t.app.cfg.low_bandwidth ? LOW_PLOT_HZ : PLOT_HZ);
            t.plots_dirty = false;
        }
        watch_backlog(&t, draw(&t, plots));
        double hz = frame_hz(&t);
        next_frame += 1.0 / hz;
        if (next_frame < now)
            next_frame = now + 1.0 / hz;
        /* Wait for input until the next frame; take every key that is there. */
        for (;;) {
            int ms = (int)((next_frame - now_s()) * 1000.0);
            timeout(ms > 0 ? ms : 0);
            int ch = getch();
            if (ch == ERR)
                break;
            if (!on_key(&t, ch)) {
                go = false;
                break;
            }
            if (quit_signal)
                break;
        }
    }
    restore_terminal();
    if (quit_signal) {
        /* Stopped by a signal: die of it, so a shell sees 128 + signal (and a loop
         * around springsim stops on Ctrl-C). */
        signal(quit_signal, SIG_DFL);
        raise(quit_signal);
    }
    for (int i = 0; i < 6; i++)
        canvas_free(t.plots[i].canvas);
    canvas_free(t.scene_canvas);
    canvas_free(t.view_canvas);
    free(t.presets);
    app_free(&t.app);
    return EXIT_SUCCESS;
}
