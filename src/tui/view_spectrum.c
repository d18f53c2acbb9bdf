/* view_spectrum.c: the spectrum view. At each refresh of the plots it takes the coarse
 * samples of the last 60 s (the longest time window: the default 10 s would resolve only
 * 0.1 Hz, too coarse to part lines 0.09 Hz apart as the beating preset's are), the
 * selected mass's displacement, and shows its Hann-windowed spectrum (src/core/spectrum.c,
 * zero-padded twice for a smoother curve) in dB, from the top level down 80 dB, against
 * frequency from 0 to twice the highest natural frequency or the drive's, whichever is
 * higher (never past the Nyquist frequency). It waits for a record of MIN_BINS / that
 * end at least (its resolution 1 / record an eighth of the axis: 4 s for the default axis to 2 Hz), as a
 * shorter one has too few bins on the axis to show a line or its peak; a mass that has
 * not moved (every level at SPECTRUM_FLOOR_DB) is said so, not drawn as a floor. The natural frequencies are dotted
 * verticals labelled f1, f2, ...; the drive's harmonics that its waveform has (sine: the
 * fundamental; square and triangle: the odd ones; sawtooth: all) dashed ones labelled
 * 1×, 3×, .... With a ghost (g), its spectrum is drawn dashed under the live one, from
 * its own record through a transform of its own, both records cut to the span they share
 * (since the ghost was made). Nothing is allocated at a refresh
 * unless a transform's length changes, which it does only while the record grows to
 * 60 s, or when dt changes. */
#include "view_spectrum.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../app/ghost.h"
#include "../chart/strokes.h"
#include "../core/motor.h"
#include "draw.h"
#include "term.h"

#define HEADER_ROWS 2 /* the marker labels: the natural frequencies, then the harmonics */
#define PAD 2         /* zero padding: the transform is twice the samples' power of two */
#define MIN_GAP 2     /* columns between two markers of the harmonics, at least */
#define MIN_BINS 8    /* resolution widths across the axis, at least */

bool spectrum_view_place(struct spectrum_view *sv, struct rect area)
{
    bool ok = chart_place(&sv->chart, area, HEADER_ROWS);
    sv->shown = -1;
    return ok;
}

void spectrum_view_free(struct spectrum_view *sv)
{
    chart_free(&sv->chart);
    spectrum_free(sv->fft);
    spectrum_free(sv->ghost_fft);
    sv->fft = sv->ghost_fft = NULL;
    sv->size = sv->ghost_size = 0;
}

/* True when the motor or a force drives the chain. */
static bool driven(const struct model *m)
{
    return model_driven(m);
}

/* The harmonic after the n-th that the drive's waveform has, 0 after the last: a sine
 * has the fundamental only, a square and a triangle the odd ones, a sawtooth all. */
static int next_harmonic(const struct model *m, int n)
{
    switch (m->motor.wave) {
    case WAVE_SQUARE:
    case WAVE_TRIANGLE:
        return n + 2;
    case WAVE_SAWTOOTH:
        return n + 1;
    default:
        return 0;
    }
}

/* The frequency axis's end (Hz): twice the highest line of interest, at most nyquist. */
static double top_frequency(const struct app *app, double nyquist)
{
    const struct model *m = app->model;
    double f = 0.0;
    if (app->modes_ok)
        f = app->modes[m->n - 1];
    if (driven(m))
        f = fmax(f, m->motor.frequency);
    f = f > 0.0 ? 2.0 * f : nyquist;
    return fmin(f, nyquist);
}

/* Dot column of frequency f. */
static int freq_dot(const struct chart *c, double f)
{
    return (int)lround(axis_dot(&c->xa, f));
}

/* The newest run of samples dt apart covering at most span seconds: a change of dt ends
 * a run. *first gets its first record, *step the spacing; returns its length. */
static int uniform_run(const struct trail *tr, double span, const double **first, double *step)
{
    const double *rec = trail_first(tr);
    int w = tr->width, last = tr->count - 1;
    if (last < 1)
        return 0;
    double t1 = rec[(size_t)last * w + TRAIL_T];
    double d = t1 - rec[(size_t)(last - 1) * w + TRAIL_T];
    int i = last - 1;
    while (i > 0) {
        double t0 = rec[(size_t)(i - 1) * w + TRAIL_T], t = rec[(size_t)i * w + TRAIL_T];
        if (fabs(t - t0 - d) > 1e-6 * d || t1 - t0 > span + 0.5 * d)
            break;
        i--;
    }
    *first = rec + (size_t)i * w;
    *step = d;
    return last - i + 1;
}

/* One record's spectrum: the selected mass's newest uniform run of samples in tr, over
 * at most span seconds, through *fft, kept at *size points (a length is kept while the
 * samples still fit it twice, so a run that wavers about a power of two does not plan
 * again at every refresh). Sets *step to the samples' spacing and returns how many there
 * were, 0 when too few, -1 on no memory. */
static int transform(struct spectrum **fft, int *size, const struct trail *tr, int mass,
                     double span, double *step)
{
    const double *first;
    int count = uniform_run(tr, span, &first, step);
    if (count < 4)
        return 0;
    int want = spectrum_length(count, PAD);
    int n = *size >= want && *size <= 2 * want ? *size : want;
    if (!*fft)
        *fft = spectrum_new();
    if (!*fft || spectrum_compute(*fft, first + TRAIL_X(tr, mass), count, (size_t)tr->width,
                                  n) != 0) {
        *size = 0;
        return -1;
    }
    *size = n;
    return count;
}

/* The level of spectrum fft (bins bin_hz apart) at dot column x: the highest bin the
 * column covers, or between bins (closer than the dots) the straight line through the
 * two nearest. */
static double column_level(const struct chart *c, const struct spectrum *fft, int x,
                           double bin_hz)
{
    const double *level = spectrum_db(fft);
    int bins = spectrum_bins(fft);
    double lo = axis_value(&c->xa, x - 0.5) / bin_hz, hi = axis_value(&c->xa, x + 0.5) / bin_hz;
    int kl = (int)ceil(fmax(lo, 0.0)), kh = (int)floor(fmin(hi, bins - 1.0));
    if (kl <= kh) {
        double best = level[kl];
        for (int k = kl + 1; k <= kh; k++)
            best = fmax(best, level[k]);
        return best;
    }
    double k = 0.5 * (lo + hi);
    int k0 = (int)floor(k);
    if (k0 < 0 || k0 + 1 >= bins)
        return NAN;
    return level[k0] + (k - k0) * (level[k0 + 1] - level[k0]);
}

/* The dot row of spectrum fft at dot column x, held to the canvas; -1 where it has none
 * (below 0 Hz, past the last bin). */
static int trace_dot(const struct chart *c, const struct spectrum *fft, int x, double bin_hz)
{
    double v = column_level(c, fft, x, bin_hz);
    if (!isfinite(v))
        return -1;
    int y = chart_dot_y(c, v), H = 4 * c->canvas->rows;
    return y < 0 ? 0 : y >= H ? H - 1 : y;
}

/* Spectrum fft as a line, each dot column joined to the one before; dashed (the
 * ghost's) or solid. */
static void draw_trace(struct chart *c, const struct spectrum *fft, double bin_hz, uint8_t color,
                  bool dash)
{
    /* The strokes for pixels keep each column's level unrounded (held to the canvas as
     * the dots are). */
    struct strokes *keep = c->canvas->strokes;
    if (keep)
        strokes_begin(keep, color, dash ? STROKE_DASHED : STROKE_LINE);
    c->canvas->mute++;
    for (int x = 0, py = -1; x < 2 * c->canvas->cols; x++) {
        int y = trace_dot(c, fft, x, bin_hz);
        if (y >= 0 && py >= 0)
            canvas_dashed_line(c->canvas, x - 1, py, x, y, color, dash);
        else if (y >= 0 && !(dash && x / 2 % 2))
            canvas_set(c->canvas, x, y, color);
        if (keep) {
            double v = column_level(c, fft, x, bin_hz), H = 4.0 * c->canvas->rows;
            strokes_point(keep, x, isfinite(v) ? fmin(fmax(chart_dot_yf(c, v), 0.0), H - 1.0)
                                               : NAN);
        }
        py = y;
    }
    c->canvas->mute--;
}

/* A marker at dot column x: a stem from the spectrum down to the floor, every dot of
 * the pattern's period whose row % period is below on. */
static void stem(struct spectrum_view *sv, int x, double bin_hz, int period, int on, int pair)
{
    struct canvas *cv = sv->chart.canvas;
    int top = trace_dot(&sv->chart, sv->fft, x, bin_hz);
    if (top < 0 || x >= 2 * cv->cols)
        return;
    for (int y = top + 1; y < 4 * cv->rows; y++)
        if (y % period < on)
            canvas_set(cv, x, y, (uint8_t)pair);
}

/* The markers, each a stem under the spectrum at its frequency (so a line standing on
 * it reads at once): the natural frequencies dotted, the drive's harmonics dashed in the
 * motor's colour. Harmonics closer than MIN_GAP columns to the one before are left out. */
static void draw_markers(struct spectrum_view *sv, const struct app *app, double fend,
                         double bin_hz)
{
    const struct model *m = app->model;
    struct chart *c = &sv->chart;
    for (int j = 0; j < m->n && app->modes_ok; j++)
        if (app->modes[j] <= fend)
            stem(sv, freq_dot(c, app->modes[j]), bin_hz, 3, 1, 0);
    if (!driven(m))
        return;
    int last = -2 * c->canvas->cols;
    for (int n = 1; n > 0 && n * m->motor.frequency <= fend; n = next_harmonic(m, n)) {
        int x = freq_dot(c, n * m->motor.frequency);
        if (x - last < 2 * MIN_GAP)
            continue;
        last = x;
        stem(sv, x, bin_hz, 4, 2, PAIR_MOTOR);
    }
}

/* The highest level of fft from 0 Hz to the axis's right end (bins bin_hz apart); *hz
 * gets its frequency. */
static double peak(const struct chart *c, const struct spectrum *fft, double bin_hz, double *hz)
{
    const double *level = spectrum_db(fft);
    double right = axis_value(&c->xa, 2 * c->canvas->cols - 0.5);
    int kmax = (int)fmin(spectrum_bins(fft) - 1.0, floor(right / bin_hz));
    int kp = 0;
    for (int k = 1; k <= kmax; k++)
        if (level[k] > level[kp])
            kp = k;
    *hz = kp * bin_hz;
    return level[kp];
}

/* Takes the newest samples: the spectrum (and the ghost's), the axes, the canvas. */
static void take_samples(struct spectrum_view *sv, const struct app *app)
{
    struct chart *c = &sv->chart;
    int mass = sv->mass < app->model->n ? sv->mass : 0;
    double step, gstep = 0.0;
    sv->shown = -1;
    if (!c->canvas)
        return;
    /* With a ghost both records are cut to the span they share (the ghost's begins when
     * it was made), so the two spectra cover the same instants and are equal until
     * something is changed; a longer live record would differ in resolution and
     * transients and seem to part from a ghost that has not. */
    double span = SPECTRUM_VIEW_SECONDS;
    sv->since_ghost = false;
    if (app->ghost) {
        const double *first;
        double lstep = 0.0, gspan = (uniform_run(app->ghost->coarse, span, &first, &gstep) - 1) * gstep;
        double lspan = (uniform_run(app->coarse, span, &first, &lstep) - 1) * lstep;
        sv->since_ghost = gspan < lspan;
        span = fmax(fmin(gspan, lspan), 0.0);
    }
    int count = transform(&sv->fft, &sv->size, app->coarse, mass, span, &step);
    sv->no_memory = count < 0;
    sv->still = false;
    sv->need = sv->span = 0.0;
    if (count <= 0)
        return;
    double fend = top_frequency(app, 0.5 / step);
    sv->span = (count - 1) * step;
    if (count * step < MIN_BINS / fend) {
        sv->need = MIN_BINS / fend;
        return;
    }
    /* The ghost's own record: its dt, and so its spacing, may differ. */
    sv->ghost_shown = app->ghost &&
                      transform(&sv->ghost_fft, &sv->ghost_size, app->ghost->coarse, mass,
                                span, &gstep) > 0;
    double bin_hz = spectrum_bin_hz(sv->fft, 1, step);
    double gbin_hz = sv->ghost_shown ? spectrum_bin_hz(sv->ghost_fft, 1, gstep) : 0.0;
    chart_fix_x(c, 0.0, fend);
    /* The axis's top: a multiple of 10 dB above the highest peak, live or ghost, that
     * moves only when a peak passes it or they all fall 20 dB below it. */
    sv->peak_db = peak(c, sv->fft, bin_hz, &sv->peak_hz);
    double hz, top = sv->peak_db;
    if (sv->ghost_shown)
        top = fmax(top, peak(c, sv->ghost_fft, gbin_hz, &hz));
    if (top <= SPECTRUM_FLOOR_DB) {
        sv->still = true;
        return;
    }
    sv->shown = mass;
    if (top > sv->top || top < sv->top - 20.0)
        sv->top = 10.0 * ceil(fmax(top, -250.0) / 10.0);
    chart_fix_y(c, sv->top - SPECTRUM_VIEW_RANGE_DB, sv->top);
    canvas_clear(c->canvas);
    draw_markers(sv, app, fend, bin_hz);
    uint8_t color = (uint8_t)(PAIR_MASS + mass % 10);
    if (sv->ghost_shown)
        draw_trace(c, sv->ghost_fft, gbin_hz, color, true);
    draw_trace(c, sv->fft, bin_hz, color, false);
}

/* A label centred on dot column x of the drawing area, in row y, if it fits after
 * column *free; *free moves past it. */
static void marker_label(const struct chart *c, int y, int x, const char *text, attr_t a,
                         int *free)
{
    int len = draw_width(text), col = c->area.x + x / 2 - (len - 1) / 2;
    if (col < *free || col + len > c->area.x + c->area.w)
        return;
    draw_text_attr(y, col, len, a, text);
    *free = col + len + 1;
}

/* The labels above the drawing area: f1, f2, ... on the first row, the harmonics on the
 * second, "dB" over the level axis. */
static void draw_labels(const struct spectrum_view *sv, const struct app *app)
{
    const struct chart *c = &sv->chart;
    const struct model *m = app->model;
    int W = 2 * c->area.w, y = c->area.y - HEADER_ROWS;
    if (y <= c->frame.y)
        return;
    draw_text(y + 1, c->area.x - 3, 2, "dB");
    int free = c->area.x;
    char text[16];
    for (int j = 0; j < m->n && app->modes_ok; j++) {
        int x = freq_dot(c, app->modes[j]);
        if (x < 0 || x >= W)
            continue;
        snprintf(text, sizeof text, "f%d", j + 1);
        marker_label(c, y, x, text, A_BOLD, &free);
    }
    if (!driven(m))
        return;
    free = c->area.x;
    for (int n = 1; n > 0; n = next_harmonic(m, n)) {
        int x = freq_dot(c, n * m->motor.frequency);
        if (x < 0 || x >= W)
            break;
        snprintf(text, sizeof text, "%d×", n);
        marker_label(c, y + 1, x, text, term_attr(PAIR_MOTOR) | A_BOLD, &free);
    }
}

void spectrum_view_draw(struct spectrum_view *sv, const struct app *app, bool fresh)
{
    struct chart *c = &sv->chart;
    const struct model *m = app->model;
    if (fresh)
        take_samples(sv, app);
    int mass = (sv->shown >= 0 ? sv->shown : sv->mass) + 1;
    char title[120], brief[60], span[24];
    if (sv->span < SPECTRUM_VIEW_SECONDS - 0.5)
        snprintf(span, sizeof span, "%.0f s so far", sv->span);
    else
        snprintf(span, sizeof span, "the last %.0f s", SPECTRUM_VIEW_SECONDS);
    snprintf(title, sizeof title,
             "Spectrum of mass %d's displacement: dB re 1 m, Hann window over %s", mass, span);
    snprintf(brief, sizeof brief, "Spectrum of mass %d (dB), %s", mass, span);
    if (sv->shown < 0) {
        /* Empty axes and the reason above them. */
        c->xt.n = c->yt.n = 0;
        if (c->canvas)
            canvas_clear(c->canvas);
        chart_draw(c, title, brief, NULL, NULL, 0);
        struct rect f = c->frame;
        /* The reason, shortened to the words before its ':' where it does not fit. */
        char why[96];
        if (sv->no_memory)
            snprintf(why, sizeof why, "no memory for the transform");
        else if (sv->still)
            snprintf(why, sizeof why, "mass %d has not moved: no spectrum to show", mass);
        else if (sv->need > 0.0)
            snprintf(why, sizeof why, "needs %.1f s of samples: %.1f s %s", sv->need, sv->span,
                     sv->since_ghost ? "since the ghost was made" : "so far");
        else
            snprintf(why, sizeof why, "not enough samples yet: space runs");
        char *colon = strchr(why, ':');
        if (draw_width(why) > f.w - 4 && colon)
            *colon = '\0';
        draw_text(f.y + 1, f.x + 2, f.w - 4, why);
        return;
    }
    char mass_key[24], peak_text[48], drive[64], modes[32];
    snprintf(mass_key, sizeof mass_key, "━ mass %d", mass);
    snprintf(peak_text, sizeof peak_text, "peak %.3f Hz %.1f dB", sv->peak_hz, sv->peak_db);
    int next = next_harmonic(m, 1);
    snprintf(drive, sizeof drive, "┃ drive %.3f Hz%s", m->motor.frequency,
             next == 3 ? ", odd harmonics" : next == 2 ? ", all harmonics" : "");
    if (m->n > 1)
        snprintf(modes, sizeof modes, "┊ natural f1..f%d", m->n);
    else
        snprintf(modes, sizeof modes, "┊ natural f1");
    struct legend_item legend[5];
    int k = 0;
    legend[k++] = (struct legend_item){mass_key, PAIR_MASS + sv->shown % 10};
    legend[k++] = (struct legend_item){peak_text, 0};
    if (sv->ghost_shown && app->ghost)
        legend[k++] = (struct legend_item){"┄ghost", PAIR_WALL};
    if (driven(m))
        legend[k++] = (struct legend_item){drive, PAIR_MOTOR};
    if (app->modes_ok)
        legend[k++] = (struct legend_item){modes, 0};
    chart_draw(c, title, brief, "Hz", legend, k);
    snprintf(title, sizeof title, "Spectrum of mass %d's displacement", mass);
    chart_report(c, title, "frequency f (Hz)", "level (dB re 1 m)");
    snprintf(c->report.name[FIG_MASS + sv->shown % 10], sizeof c->report.name[0], "mass %d", mass);
    draw_labels(sv, app);
}
