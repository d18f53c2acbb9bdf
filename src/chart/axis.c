/* axis.c: axes on whole cells. Ticks are 1, 2, 5 x 10^k with the ends rounded outward
 * (gnuplot's axis.c); the gap between ticks is a whole number of cells, the same for
 * every gap, and the value-to-dot map is linear over the whole axis, so a gridline never
 * has to be rounded to a row. Labels are built from the tick's integer count of the
 * step's decade, so they are exact and never carry floating-point noise. */
#include "axis.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WIDEN_MAX 200 /* step widenings, at most: 1e-300 to 1e300 is about 1800 / 3 */

enum form { FORM_PLAIN, FORM_EXP, FORM_ROUGH };

/* The exponent e of a 1-2-5 step's decade 10^e. */
static int decade(double step)
{
    return (int)floor(log10(step) + 1e-9);
}

/* The 1-2-5 step next above or below step (dir +1 or -1). */
static double step_next(double step, int dir)
{
    double mag = pow(10.0, decade(step)), m = step / mag;
    if (dir > 0)
        return (m < 1.5 ? 2.0 : m < 3.5 ? 5.0 : 10.0) * mag;
    return (m < 1.5 ? 0.5 : m < 3.5 ? 1.0 : 2.0) * mag;
}

double axis_step(double lo, double hi, int max_ticks)
{
    if (!(hi - lo > 0.0) || !isfinite(hi - lo))
        return 1.0;
    if (max_ticks < 1)
        max_ticks = 1;
    double raw = (hi - lo) / max_ticks;
    double mag = pow(10.0, floor(log10(raw)));
    static const double nice[] = {1.0, 2.0, 5.0};
    for (int i = 0; i < 3; i++)
        if (nice[i] * mag >= raw * (1.0 - 1e-9))
            return nice[i] * mag;
    return 10.0 * mag;
}

void axis_round_out(double *lo, double *hi, double step)
{
    *lo = floor(*lo / step + 1e-9) * step;
    *hi = ceil(*hi / step - 1e-9) * step;
    if (*hi <= *lo)
        *hi = *lo + step;
}

/* True when v is a whole multiple of step (to rounding). */
static bool on_tick(double v, double step)
{
    double q = v / step;
    return fabs(q) < 1e15 && fabs(q - round(q)) < 1e-6;
}

/* Tick k as a whole number of units of 10^e; false when it does not fit a long long
 * comfortably (an offset huge beside the step). */
static bool tick_units(const struct axis *a, int k, int e, long long *n)
{
    double unit = pow(10.0, e);
    double u = a->lo / unit + k * (a->step / unit);
    if (!(fabs(u) < 1e15))
        return false;
    *n = llround(u);
    return true;
}

/* v's decimal digits into d, zero-padded to at least min of them; their count. By hand:
 * labels are formatted for every tick at every refresh, and snprintf was most of that. */
static int put_digits(unsigned long long v, int min, char *d)
{
    char r[24];
    int n = 0;
    do {
        r[n++] = (char)('0' + v % 10);
        v /= 10;
    } while (v);
    while (n < min && n < (int)sizeof r)
        r[n++] = '0';
    for (int i = 0; i < n; i++)
        d[i] = r[n - 1 - i];
    d[n] = '\0';
    return n;
}

/* The pieces given (NULL-ended) joined into out[32], cut as snprintf would; the length
 * uncut. */
static int join(char *out, const char *const *piece)
{
    int len = 0;
    for (; *piece; piece++)
        for (const char *p = *piece; *p; p++, len++)
            if (len < 31)
                out[len] = *p;
    out[len < 31 ? len : 31] = '\0';
    return len;
}

static unsigned long long magnitude(long long n)
{
    return n < 0 ? 0ULL - (unsigned long long)n : (unsigned long long)n;
}

/* n x 10^e in plain decimals (e < 0: -e decimals) into out[32]; its length, or a length
 * over AXIS_LABEL_MAX when it could not fit anyway. */
static int format_plain(long long n, int e, char *out)
{
    if (e > 15 || e < -15)
        return 99;
    char d[40], whole[40], zeros[16] = "";
    int len = put_digits(magnitude(n), e < 0 ? 1 - e : 1, d);
    const char *sign = n < 0 ? "-" : "";
    if (e >= 0) {
        for (int i = 0; n && i < e; i++)
            zeros[i] = '0', zeros[i + 1] = '\0';
        return join(out, (const char *const[]){sign, d, zeros, NULL});
    }
    int w = len + e; /* digits before the point (>= 1: zero-padded above) */
    memcpy(whole, d, (size_t)w);
    whole[w] = '\0';
    return join(out, (const char *const[]){sign, whole, ".", d + w, NULL});
}

/* n x 10^e as m.mmm e x with m 1..9 and no trailing zeros ("-2e4", "1.5e-5"). */
static int format_exp(long long n, int e, char *out)
{
    if (n == 0)
        return join(out, (const char *const[]){"0", NULL});
    char d[24], x[16], lead[2];
    int len = put_digits(magnitude(n), 1, d);
    int ex = e + len - 1;
    while (len > 1 && d[len - 1] == '0')
        d[--len] = '\0';
    const char *sign = n < 0 ? "-" : "";
    x[0] = 'e';
    if (ex < 0)
        x[1] = '-', put_digits(magnitude(ex), 1, x + 2);
    else
        put_digits((unsigned long long)ex, 1, x + 1);
    if (len == 1)
        return join(out, (const char *const[]){sign, d, x, NULL});
    lead[0] = d[0], lead[1] = '\0';
    return join(out, (const char *const[]){sign, lead, ".", d + 1, x, NULL});
}

/* v to one significant digit: for an axis no exact label fits (only a hand-made one:
 * axis_fit widens the step until they do). At most 7 columns for any double. */
static int format_rough(double v, char *out)
{
    if (!isfinite(v))
        return join(out, (const char *const[]){"?", NULL});
    if (v == 0.0)
        return join(out, (const char *const[]){"0", NULL});
    int e = (int)floor(log10(fabs(v)));
    /* 10^e underflows below 1e-308: scale v up first. */
    double m = e < -300 ? v * 1e300 / pow(10.0, e + 300) : v / pow(10.0, e);
    return format_exp(llround(m), e, out);
}

/* Tick k's label in form f into out[32]; its length. */
static int format_tick(const struct axis *a, int k, enum form f, char *out)
{
    int e = decade(a->step);
    long long n;
    if (f == FORM_ROUGH || !tick_units(a, k, e, &n))
        return format_rough(a->lo + k * a->step, out);
    return f == FORM_PLAIN ? format_plain(n, e, out) : format_exp(n, e, out);
}

/* The form every label of a takes: plain if all fit, else exponent if all fit, else
 * rough; *width gets the widest label. */
static enum form label_form(const struct axis *a, int *width)
{
    char buf[32];
    if (a->step > 0.0 && isfinite(a->step) && isfinite(a->lo))
        for (enum form f = FORM_PLAIN; f < FORM_ROUGH; f++) {
            int e = decade(a->step), w = 0;
            long long n;
            for (int k = 0; k <= a->intervals && w <= AXIS_LABEL_MAX; k++) {
                int len = tick_units(a, k, e, &n) ? format_tick(a, k, f, buf) : 99;
                if (len > w)
                    w = len;
            }
            if (w <= AXIS_LABEL_MAX) {
                *width = w;
                return f;
            }
        }
    *width = 0;
    for (int k = 0; k <= a->intervals; k++) {
        int len = format_tick(a, k, FORM_ROUGH, buf);
        if (len > *width)
            *width = len;
    }
    return FORM_ROUGH;
}

/* Rounds [lo, hi] out to multiples of step and places the ticks on the cells. */
static void lay(struct axis *a, double lo, double hi, double step, bool anchored)
{
    double klo = floor(lo / step + 1e-9), khi = ceil(hi / step - 1e-9);
    if (khi <= klo)
        khi = klo + 1.0;
    a->lo = klo * step;
    a->step = step;
    a->intervals = (int)(khi - klo);
    int room = (a->cells - 1) / a->intervals; /* 0: the ticks do not all fit */
    a->spacing = room < 1 ? 1 : room;
    int leftover = a->cells - 1 - a->intervals * a->spacing;
    a->first = anchored ? leftover : leftover / 2;
}

/* Ranges narrower than this (m or any unit) are shown as [-1, 1]: their steps would be
 * subnormal. */
#define AXIS_TINY 1e-290

static void fit(struct axis *a, double lo, double hi, int max_ticks, int cells, int dpc,
                int min_spacing, bool anchored)
{
    if (!isfinite(lo) || !isfinite(hi))
        lo = -1.0, hi = 1.0;
    lo = fmin(fmax(lo, -1e300), 1e300); /* so that hi - lo stays finite */
    hi = fmin(fmax(hi, -1e300), 1e300);
    if (hi < lo) {
        double t = lo;
        lo = hi, hi = t;
    }
    if (hi - lo <= 1e-12 * fmax(fabs(lo), fabs(hi))) {
        double pad = lo != 0.0 ? 0.1 * fabs(lo) : 1.0;
        lo -= pad, hi += pad;
    }
    if (!(hi - lo >= AXIS_TINY)) /* subnormal data: no step to show it on */
        lo = -1.0, hi = 1.0;
    if (max_ticks < 1)
        max_ticks = 1;
    a->cells = cells < 1 ? 1 : cells;
    a->dpc = dpc < 1 ? 1 : dpc;
    double step = axis_step(lo, hi, max_ticks), finer = step_next(step, -1);
    /* A range already on ticks of the finer step (a scale's range, rounded out with
     * max_ticks intervals before) is kept as it is, not rounded out a second time. */
    if (on_tick(lo, finer) && on_tick(hi, finer) && (hi - lo) / finer <= max_ticks + 1.0 + 1e-6)
        step = finer;
    double far = fmax(fabs(lo), fabs(hi));
    for (int i = 0; i < WIDEN_MAX; i++) {
        lay(a, lo, hi, step, anchored);
        int width;
        bool labels_fit = label_form(a, &width) != FORM_ROUGH;
        /* One interval is as few as there can be; past far, the ticks are -step, 0, step
         * at most, and a wider step changes nothing. */
        bool room = a->intervals * a->spacing <= a->cells - 1;
        if (labels_fit && ((room && a->spacing >= min_spacing) || a->intervals == 1 || step >= far))
            return;
        step = step_next(step, +1);
    }
}

void axis_fit(struct axis *a, double lo, double hi, int max_ticks, int cells, int dpc,
              int min_spacing)
{
    fit(a, lo, hi, max_ticks, cells, dpc, min_spacing, false);
}

/* The span of values an axis shows on its cells. */
static double shown_span(const struct axis *a)
{
    return a->cells * a->step / a->spacing;
}

/* Axis a laid with its ticks inside [lo, hi] on step: the widest whole spacing that
 * keeps [lo, hi] on the cells (a scale's range, padded already: its ends may take the
 * outer cells' edges), [lo, hi] centred. False when that is under min_spacing,
 * fewer than two ticks fall inside, or the labels do not fit. */
static bool lay_inside(struct axis *a, double lo, double hi, double step, int min_spacing)
{
    double room = floor(a->cells * step / (hi - lo) + 1e-9); /* may be huge: no int yet */
    double k0 = ceil(lo / step - 1e-9), k1 = floor(hi / step + 1e-9);
    if (!(room >= min_spacing && room <= a->cells) || k1 - k0 < 1.0 ||
        (k1 - k0) * room > a->cells - 1)
        return false;
    int spacing = (int)room;
    a->lo = k0 * step;
    a->step = step;
    a->intervals = (int)(k1 - k0);
    a->spacing = spacing;
    /* Tick 0's cell: lo no lower than the first cell's lower edge, hi no higher than the
     * last cell's upper edge, and as near as that allows to [lo, hi] centred. */
    double below = (lo - a->lo) / step * spacing, above = (hi - a->lo) / step * spacing;
    double least = ceil(-0.5 - below - 1e-9), most = floor(a->cells - 0.5 - above + 1e-9);
    double mid = floor(0.5 * (a->cells - 1) - 0.5 * (below + above) + 0.5);
    mid = fmin(fmax(mid, least), most);
    if (!(least <= most && mid >= 0.0 && mid < a->cells))
        return false;
    a->first = (int)mid;
    int last = a->first + a->intervals * spacing, width;
    return a->first >= 0 && last <= a->cells - 1 && label_form(a, &width) != FORM_ROUGH;
}

void axis_fit_inside(struct axis *a, double lo, double hi, int max_ticks, int cells, int dpc,
                     int min_spacing)
{
    fit(a, lo, hi, max_ticks, cells, dpc, min_spacing, false);
    if (!(hi - lo >= AXIS_TINY) || !isfinite(hi - lo))
        return;
    /* The steps around the one the ticks would take, finest first: the first whose
     * layout shows less than the rounded-out one wins. */
    double step = step_next(axis_step(lo, hi, max_ticks), -1);
    for (int i = 0; i < 3; i++, step = step_next(step, +1)) {
        struct axis b = *a;
        if (lay_inside(&b, lo, hi, step, min_spacing) && shown_span(&b) < shown_span(a)) {
            *a = b;
            return;
        }
    }
}

/* Moves a rolling axis laid on [-window, 0] (its step and spacing) to absolute time: the
 * last cell is the one (in whole cells counted from t = 0) that holds end, and the ticks
 * are the multiples of the step that fall on the cells. */
static void roll(struct axis *a, double end)
{
    /* Cells are counted in whole units of step/spacing from t = 0, so a tick (a multiple
     * of the step) is on a cell exactly when its unit count is a multiple of spacing. */
    double n_end = ceil(end / a->step * a->spacing - 0.5 + 1e-6); /* end on the last cell */
    /* Until the axis is full, it starts at 0 and the trace fills it from the left. */
    n_end = fmax(n_end, a->cells - 1);
    double n_left = n_end - (a->cells - 1);
    double k0 = ceil(n_left / a->spacing - 1e-9), k1 = floor(n_end / a->spacing + 1e-9);
    a->lo = k0 * a->step;
    a->first = (int)(k0 * a->spacing - n_left);
    a->intervals = k1 > k0 ? (int)(k1 - k0) : 1;
}

void axis_fit_rolling(struct axis *a, double end, double window, int max_ticks, int cells,
                      int dpc, int min_spacing)
{
    if (!isfinite(end))
        end = 0.0;
    if (!(window > 0.0) || !isfinite(window))
        window = 1.0;
    fit(a, -window, 0.0, max_ticks, cells, dpc, min_spacing, true);
    for (int i = 0; i < WIDEN_MAX; i++) {
        roll(a, end);
        int width;
        if (label_form(a, &width) != FORM_ROUGH)
            return;
        /* The absolute labels are wider than the relative ones were: a wider step. */
        lay(a, -window, 0.0, step_next(a->step, +1), true);
    }
}

/* dot = first*dpc + (dpc - 1)/2 + (v - lo)/step * spacing*dpc: linear, one tick step to
 * spacing cells, tick 0 on the middle of cell `first`. */
double axis_dot(const struct axis *a, double v)
{
    double centre = a->first * a->dpc + 0.5 * (a->dpc - 1);
    return centre + (v - a->lo) / a->step * (a->spacing * a->dpc);
}

double axis_value(const struct axis *a, double d)
{
    double centre = a->first * a->dpc + 0.5 * (a->dpc - 1);
    return a->lo + (d - centre) / (a->spacing * a->dpc) * a->step;
}

void axis_label(const struct axis *a, int k, char *buf, size_t len)
{
    int width;
    char out[32];
    format_tick(a, k, label_form(a, &width), out);
    snprintf(buf, len, "%s", out);
}

int axis_label_width(const struct axis *a)
{
    int width;
    label_form(a, &width);
    return width;
}
