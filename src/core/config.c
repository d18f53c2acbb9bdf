/* config.c: the option table shared by the command line and presets, and the checks
 * every value goes through, whichever way it came in. */
#include "config.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const struct config_option config_options[CFG_KEY_COUNT] = {
    [CFG_PRESET] = {"preset", 'p', NULL, "NAME|FILE",
                    "load a preset by name or file path (applied before other options)"},
    [CFG_MASSES] = {"masses", 'n', "system", "N", "number of masses (1 to 1000; default 2)"},
    [CFG_MASS] = {"mass", 0, "system", "LIST", "kg: one value for all, or N values (default 1)"},
    [CFG_SPRING] = {"spring", 0, "system", "LIST", "N/m: one value, or N+1 values (default 10)"},
    [CFG_DAMPING] = {"damping", 0, "system", "LIST",
                     "N s/m: one value, or N values (default 0.1)"},
    [CFG_DT] = {"dt", 0, "system", "SECONDS", "time step, 0 < dt <= 0.05 (default 0.01)"},
    [CFG_INTEGRATOR] = {"integrator", 0, "system", "euler|semi-implicit|verlet|rk4|exact",
                        "how each step is taken (default rk4)"},
    [CFG_BOUNDARY] = {"boundary", 0, "motor", "motor|wall|free", "right end (default motor)"},
    [CFG_WAVE] = {"wave", 0, "motor", "sine|square|triangle|sawtooth",
                  "motor waveform (default sine)"},
    [CFG_AMPLITUDE] = {"amplitude", 0, "motor", "METRES", "motor amplitude >= 0 (default 1)"},
    [CFG_FREQUENCY] = {"frequency", 0, "motor", "HZ", "motor frequency, 0 < f <= 1e6 (default 1)"},
    [CFG_X0] = {"x0", 0, "initial", "LIST", "initial displacements (m): one value or N values"},
    [CFG_V0] = {"v0", 0, "initial", "LIST", "initial velocities (m/s): one value or N values"},
    [CFG_RANDOM] = {"random", 0, "initial", NULL,
                    "random initial positions (minimum separation kept)"},
    [CFG_SEED] = {"seed", 0, "initial", "N", "seed for --random (same seed, same positions)"},
    [CFG_NO_COLLISIONS] = {"no-collisions", 0, "system", NULL,
                           "turn collisions off (the velocity cap stays)"},
    [CFG_DURATION] = {"duration", 0, "run", "SECONDS", "headless run length >= 0 (default 10)"},
    [CFG_SAMPLE] = {"sample", 0, "run", "SECONDS",
                    "headless output interval, rounded to whole steps (default every step)"},
    [CFG_OUTPUT] = {"output", 'o', NULL, "FILE",
                    "headless/modes/sweep output to FILE instead of standard output"},
    [CFG_ENERGY] = {"energy", 0, "run", NULL,
                    "headless CSV gains kinetic,potential,dissipated,motor_work,contact"},
    [CFG_FPS] = {"fps", 0, "run", "N", "interactive frames per second, 1 to 60 (default 30)"},
    [CFG_LOW_BANDWIDTH] = {"low-bandwidth", 0, "run", NULL,
                           "interactive: fewer frames and plot refreshes (slow links)"},
};

/* What each key allows, quoted in every error about it. */
static const char *const expected[CFG_KEY_COUNT] = {
    [CFG_PRESET] = "a preset name or file",
    [CFG_MASSES] = "1 <= N <= 1000",
    [CFG_MASS] = "masses > 0 kg: one value, or one per mass",
    [CFG_SPRING] = "springs > 0 N/m: one value, or N+1",
    [CFG_DAMPING] = "damping >= 0 N s/m: one value, or one per mass",
    [CFG_DT] = "0 < dt <= 0.05",
    [CFG_INTEGRATOR] = "euler, semi-implicit, verlet, rk4 or exact",
    [CFG_BOUNDARY] = "motor, wall or free",
    [CFG_WAVE] = "sine, square, triangle or sawtooth",
    [CFG_AMPLITUDE] = "amplitude >= 0 m",
    [CFG_FREQUENCY] = "0 < frequency <= 1e6 Hz",
    [CFG_X0] = "displacements in m: one value, or one per mass",
    [CFG_V0] = "velocities in m/s: one value, or one per mass",
    [CFG_RANDOM] = "true or false",
    [CFG_SEED] = "a whole number 0 <= seed < 2^64",
    [CFG_NO_COLLISIONS] = "true or false",
    [CFG_DURATION] = "duration >= 0 s",
    [CFG_SAMPLE] = "sample > 0 s",
    [CFG_OUTPUT] = "a file name",
    [CFG_ENERGY] = "true or false",
    [CFG_FPS] = "1 <= fps <= 60",
    [CFG_LOW_BANDWIDTH] = "true or false",
};

/* Lower bounds of numeric keys: value > lo (open) or value >= lo (closed). */
enum bound { ANY, GT0, GE0 };

void config_init(struct config *c)
{
    memset(c, 0, sizeof *c);
    c->masses = 2;
    c->dt = 0.01;
    c->integrator = INTEGRATOR_RK4;
    c->boundary = BOUNDARY_MOTOR;
    c->wave = WAVE_SINE;
    c->amplitude = 1.0;
    c->frequency = 1.0;
    c->duration = 10.0;
    c->fps = 30;
}

int config_find(const char *name)
{
    for (int k = 0; k < CFG_KEY_COUNT; k++)
        if (strcmp(name, config_options[k].name) == 0)
            return k;
    return -1;
}

/* Appends byte c to buf (room for len, NUL kept) at *used, escaped if it is a control
 * byte: C's escapes for the common ones, \xNN for the rest. */
static void put_escaped(unsigned char c, char *buf, size_t len, size_t *used)
{
    static const char named[] = "\a\b\t\n\v\f\r";
    static const char letter[] = "abtnvfr";
    char one[8];
    const char *at = c ? strchr(named, c) : NULL;
    if (at)
        snprintf(one, sizeof one, "\\%c", letter[at - named]);
    else if (c < 0x20 || c == 0x7f || c >= 0x80)
        snprintf(one, sizeof one, "\\x%02x", c);
    else
        snprintf(one, sizeof one, "%c", c);
    size_t w = strlen(one);
    if (*used + w < len) {
        memcpy(buf + *used, one, w + 1);
        *used += w;
    }
}

/* Length of the valid UTF-8 sequence at s (at most n bytes) that is not a C1 control
 * (U+0080 to U+009F), or 0. */
static size_t utf8_length(const unsigned char *s, size_t n)
{
    size_t k = s[0] >= 0xf0 && s[0] <= 0xf4 ? 4 : s[0] >= 0xe0 ? 3 : s[0] >= 0xc2 ? 2 : 0;
    if (s[0] >= 0xf5 || k == 0 || k > n)
        return 0;
    for (size_t i = 1; i < k; i++)
        if ((s[i] & 0xc0) != 0x80)
            return 0;
    if (k == 2 && s[0] == 0xc2 && s[1] < 0xa0)
        return 0; /* C1 control */
    if ((k == 3 && s[0] == 0xe0 && s[1] < 0xa0) || (k == 4 && s[0] == 0xf0 && s[1] < 0x90) ||
        (k == 4 && s[0] == 0xf4 && s[1] >= 0x90) || (k == 3 && s[0] == 0xed && s[1] >= 0xa0))
        return 0; /* overlong, past U+10FFFF, or a surrogate */
    return k;
}

void config_escape(const char *text, size_t n, size_t max, char *buf, size_t len)
{
    const unsigned char *s = (const unsigned char *)text;
    size_t used = 0, i = 0;
    if (len == 0)
        return;
    buf[0] = '\0';
    while (i < n && i < max) {
        size_t k = s[i] >= 0x80 ? utf8_length(s + i, n - i) : 0;
        if (k > 0) {
            if (used + k < len) {
                memcpy(buf + used, s + i, k);
                used += k;
                buf[used] = '\0';
            }
            i += k;
        } else {
            put_escaped(s[i++], buf, len, &used);
        }
    }
    if (i < n)
        snprintf(buf + used, len - used, "...");
}

void config_quote(const char *value, size_t n, char *buf, size_t len)
{
    char text[4 * CONFIG_QUOTE_MAX + 8];
    config_escape(value, n, CONFIG_QUOTE_MAX, text, sizeof text);
    if (n <= CONFIG_QUOTE_MAX)
        snprintf(buf, len, "'%s'", text);
    else
        snprintf(buf, len, "'%s' (%zu characters)", text, n);
}

static int fail_span(int key, const char *value, size_t n, const char *why, char *err,
                     size_t errlen)
{
    char q[4 * CONFIG_QUOTE_MAX + 48];
    config_quote(value, n, q, sizeof q);
    snprintf(err, errlen, "%s %s (expected %s)", q, why, expected[key]);
    return -1;
}

static int fail(int key, const char *value, const char *why, char *err, size_t errlen)
{
    return fail_span(key, value, strlen(value), why, err, errlen);
}

/* Parses the n characters at s as one whole finite number, nothing before or after it
 * (no blanks either); returns a reason on failure. -0 reads as 0. */
static const char *parse_span(const char *s, size_t n, double *out)
{
    char *end;
    if (n == 0)
        return "is empty";
    if (isspace((unsigned char)s[0]))
        return "is not a number (it starts with a blank)";
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || end != s + n)
        return isspace((unsigned char)s[n - 1]) ? "is not a number (it ends with a blank)"
                                                : "is not a number";
    /* ERANGE with a tiny result is an underflow: a valid, very small number. */
    if (!isfinite(v) || (errno == ERANGE && fabs(v) >= 1.0))
        return "is not a finite number";
    *out = v + 0.0;
    return NULL;
}

const char *config_parse_number(const char *s, double *out)
{
    return parse_span(s, strlen(s), out);
}

static const char *parse_number(const char *s, double *out)
{
    return config_parse_number(s, out);
}

static int in_bound(double v, enum bound b)
{
    return b == ANY || (b == GT0 && v > 0.0) || (b == GE0 && v >= 0.0);
}

static int set_number(int key, const char *value, double *out, enum bound b, double hi,
                      char *err, size_t errlen)
{
    double v;
    const char *why = parse_number(value, &v);
    if (why)
        return fail(key, value, why, err, errlen);
    if (!in_bound(v, b) || v > hi)
        return fail(key, value, "is out of range", err, errlen);
    *out = v;
    return 0;
}

/* Parses a comma-separated list: numbers as parse_span reads them, with spaces or tabs
 * allowed on either side of a comma and nowhere else. Items of any length are read in
 * place. */
static int set_list(int key, const char *value, struct config_list *out, enum bound b,
                    char *err, size_t errlen)
{
    static struct config_list tmp; /* large; the parser is not reentrant anyway */
    char msg[4 * CONFIG_QUOTE_MAX + 96], q[4 * CONFIG_QUOTE_MAX + 48];
    const char *p = value;

    tmp.count = 0;
    for (;;) {
        if (tmp.count > 0)
            while (*p == ' ' || *p == '\t')
                p++;
        const char *end = strchr(p, ',');
        if (!end)
            end = p + strlen(p);
        const char *stop = end;
        if (*end == ',')
            while (stop > p && (stop[-1] == ' ' || stop[-1] == '\t'))
                stop--;
        size_t len = (size_t)(stop - p);
        if (tmp.count > MODEL_MAX_MASSES)
            return fail(key, value, "has more than 1001 values", err, errlen);
        if (len == 0 && (tmp.count > 0 || *end == ',')) {
            snprintf(msg, sizeof msg, "has an empty item (item %d)", tmp.count + 1);
            return fail(key, value, msg, err, errlen);
        }
        double v;
        const char *why = parse_span(p, len, &v);
        if (!why && !in_bound(v, b))
            why = "is out of range";
        if (why) {
            if (p == value && *end == '\0')
                return fail(key, value, why, err, errlen);
            config_quote(p, len, q, sizeof q);
            snprintf(msg, sizeof msg, "item %d %s %s", tmp.count + 1, q, why);
            return fail(key, value, msg, err, errlen);
        }
        tmp.v[tmp.count++] = v;
        if (*end == '\0')
            break;
        p = end + 1;
    }
    *out = tmp;
    return 0;
}

static int set_bool(int key, const char *value, bool *out, char *err, size_t errlen)
{
    static const char *const yes[] = {"true", "yes", "on", "1"};
    static const char *const no[] = {"false", "no", "off", "0"};
    if (!value) {
        *out = true;
        return 0;
    }
    for (size_t i = 0; i < sizeof yes / sizeof *yes; i++) {
        if (strcmp(value, yes[i]) == 0) {
            *out = true;
            return 0;
        }
        if (strcmp(value, no[i]) == 0) {
            *out = false;
            return 0;
        }
    }
    return fail(key, value, "is not true or false", err, errlen);
}

/* Whole numbers: digits only, optional sign where negatives are meaningful. */
static const char *parse_whole(const char *s, unsigned long long *out)
{
    char *end;
    if (*s == '\0')
        return "is empty";
    if (s[0] == '+' && s[1] >= '0' && s[1] <= '9')
        s++; /* +3 is 3, as strtod reads +0.01 */
    if (strspn(s, "0123456789") != strlen(s)) {
        double d;
        if (parse_number(s, &d))
            return "is not a number";
        return d < 0.0 && d == floor(d) ? "is out of range" : "is not a whole number";
    }
    errno = 0;
    unsigned long long v = strtoull(s, &end, 10);
    if (errno == ERANGE || *end != '\0')
        return "is out of range";
    *out = v;
    return NULL;
}

int config_set(struct config *c, int key, const char *value, char *err, size_t errlen)
{
    const char *why;
    unsigned long long whole;
    int e;

    if (key < 0 || key >= CFG_KEY_COUNT) {
        snprintf(err, errlen, "is not a setting");
        return -1;
    }
    if (!value && config_options[key].arg)
        return fail(key, "", "is missing", err, errlen);
    switch ((enum config_key)key) {
    case CFG_PRESET:
        return 0; /* applied by the caller, before everything else */
    case CFG_MASSES:
        if ((why = parse_whole(value, &whole)))
            return fail(key, value, why, err, errlen);
        if (whole < 1 || whole > MODEL_MAX_MASSES)
            return fail(key, value, "is out of range", err, errlen);
        c->masses = (int)whole;
        return 0;
    case CFG_MASS:
        return set_list(key, value, &c->mass, GT0, err, errlen);
    case CFG_SPRING:
        return set_list(key, value, &c->spring, GT0, err, errlen);
    case CFG_DAMPING:
        return set_list(key, value, &c->damping, GE0, err, errlen);
    case CFG_DT:
        return set_number(key, value, &c->dt, GT0, 0.05, err, errlen);
    case CFG_INTEGRATOR:
        if ((e = integrator_parse(value)) < 0)
            return fail(key, value, "is not an integrator", err, errlen);
        c->integrator = (enum integrator)e;
        return 0;
    case CFG_BOUNDARY:
        if ((e = model_boundary_parse(value)) < 0)
            return fail(key, value, "is not a right end", err, errlen);
        c->boundary = (enum boundary)e;
        return 0;
    case CFG_WAVE:
        if ((e = motor_wave_parse(value)) < 0)
            return fail(key, value, "is not a waveform", err, errlen);
        c->wave = (enum wave)e;
        return 0;
    case CFG_AMPLITUDE:
        return set_number(key, value, &c->amplitude, GE0, INFINITY, err, errlen);
    case CFG_FREQUENCY:
        /* A bound well past any mechanical drive: a square wave at f makes 2 f dt
         * sub-steps a step, so an unbounded f could make one step last forever. */
        return set_number(key, value, &c->frequency, GT0, 1e6, err, errlen);
    case CFG_X0:
        if (set_list(key, value, &c->x0, ANY, err, errlen))
            return -1;
        c->random = false; /* the later of x0 and random wins */
        return 0;
    case CFG_V0:
        return set_list(key, value, &c->v0, ANY, err, errlen);
    case CFG_RANDOM:
        if (set_bool(key, value, &c->random, err, errlen))
            return -1;
        if (c->random)
            c->x0.count = 0;
        return 0;
    case CFG_SEED:
        if ((why = parse_whole(value, &whole)))
            return fail(key, value, why, err, errlen);
        c->seed = whole;
        c->seed_set = true;
        return 0;
    case CFG_NO_COLLISIONS:
        return set_bool(key, value, &c->no_collisions, err, errlen);
    case CFG_DURATION:
        return set_number(key, value, &c->duration, GE0, INFINITY, err, errlen);
    case CFG_SAMPLE:
        return set_number(key, value, &c->sample, GT0, INFINITY, err, errlen);
    case CFG_OUTPUT:
        if (*value == '\0')
            return fail(key, value, "is empty", err, errlen);
        c->output = value;
        return 0;
    case CFG_ENERGY:
        return set_bool(key, value, &c->energy, err, errlen);
    case CFG_FPS:
        if ((why = parse_whole(value, &whole)))
            return fail(key, value, why, err, errlen);
        if (whole < 1 || whole > 60)
            return fail(key, value, "is out of range", err, errlen);
        c->fps = (int)whole;
        return 0;
    case CFG_LOW_BANDWIDTH:
        return set_bool(key, value, &c->low_bandwidth, err, errlen);
    case CFG_KEY_COUNT:
        break;
    }
    snprintf(err, errlen, "is not a setting");
    return -1;
}

int config_check_steps(const struct config *c, char *err, size_t errlen)
{
    double steps = c->duration / c->dt;
    if (steps <= CONFIG_MAX_STEPS)
        return -1;
    char count[32];
    snprintf(count, sizeof count, isfinite(steps) ? "%.3g" : "over 1e308", steps);
    snprintf(err, errlen, "a run of %g s at dt = %g s is %s steps (expected at most %g: "
             "a shorter --duration or a larger --dt)", c->duration, c->dt, count,
             CONFIG_MAX_STEPS);
    return c->dt < 1e-9 ? CFG_DT : CFG_DURATION;
}

/* Says that list l has the wrong length for this many elements, quoting its values. */
static void wrong_length(const struct config_list *l, int elements, const char *what,
                         char *err, size_t errlen)
{
    /* The first values as given (well, as read), then "..." if there are more. */
    char text[48];
    size_t used = 0;
    int i = 0;
    for (; i < l->count; i++) {
        char one[32];
        int w = snprintf(one, sizeof one, i ? ",%g" : "%g", l->v[i]);
        if (used + (size_t)w + 4 > sizeof text)
            break;
        memcpy(text + used, one, (size_t)w + 1);
        used += (size_t)w;
    }
    snprintf(err, errlen, "'%s%s' has %d values for %d %s (expected 1 or %d)", text,
             i < l->count ? ",..." : "", l->count, elements, what, elements);
}

/* Checks a list's length against the element count and expands it into dst. */
static int expand(const struct config_list *l, int elements, double fallback, double *dst,
                  const char *what, char *err, size_t errlen)
{
    if (l->count == 0) {
        for (int i = 0; i < elements; i++)
            dst[i] = fallback;
        return 0;
    }
    if (l->count != 1 && l->count != elements) {
        wrong_length(l, elements, what, err, errlen);
        return -1;
    }
    for (int i = 0; i < elements; i++)
        dst[i] = l->v[l->count == 1 ? 0 : i];
    return 0;
}

struct model *config_model(const struct config *c, int *bad_key, char *err, size_t errlen)
{
    int n = c->masses;
    struct model *m = model_new(n);
    *bad_key = -1;
    if (!m) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    const char *per_mass = n == 1 ? "mass" : "masses";
    const char *springs = "springs";
    if (expand(&c->mass, n, 1.0, m->m, per_mass, err, errlen))
        *bad_key = CFG_MASS;
    else if (expand(&c->spring, n + 1, 10.0, m->k, springs, err, errlen))
        *bad_key = CFG_SPRING;
    else if (expand(&c->damping, n, 0.1, m->c, per_mass, err, errlen))
        *bad_key = CFG_DAMPING;
    else if (c->x0.count > 1 && c->x0.count != n)
        *bad_key = CFG_X0;
    else if (c->v0.count > 1 && c->v0.count != n)
        *bad_key = CFG_V0;
    if (*bad_key == CFG_X0 || *bad_key == CFG_V0)
        wrong_length(*bad_key == CFG_X0 ? &c->x0 : &c->v0, n, per_mass, err, errlen);
    if (*bad_key >= 0) {
        model_free(m);
        return NULL;
    }
    m->boundary = c->boundary;
    m->motor = (struct motor){c->wave, c->amplitude, c->frequency, 0.0};
    m->collisions = !c->no_collisions;
    return m;
}

/* splitmix64 (Steele, Lea and Flood 2014): small, fast, and fixed across platforms. */
static uint64_t splitmix64(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

static int compare_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

void config_random_positions(const struct model *m, uint64_t seed, double *x)
{
    int n = m->n;
    double w = model_block_width(m);
    double sep = 1.5 * w;
    double lo = 0.5 * w;
    double hi = MODEL_LENGTH - 0.5 * w;
    if (m->boundary == BOUNDARY_MOTOR && hi - m->motor.amplitude - lo > (n - 1) * sep)
        hi -= m->motor.amplitude; /* clear of the piston at its furthest in */
    /* n sorted uniforms on [0, room], spread by sep: uniform over the allowed set. */
    double room = (hi - lo) - (n - 1) * sep;
    uint64_t state = seed;
    for (int i = 0; i < n; i++)
        x[i] = room * (double)(splitmix64(&state) >> 11) * 0x1.0p-53;
    qsort(x, (size_t)n, sizeof *x, compare_double);
    for (int i = 0; i < n; i++)
        x[i] = lo + x[i] + i * sep - model_equilibrium(m, i);
}

void config_initial(const struct config *c, const struct model *m, double *x, double *v)
{
    int n = m->n;
    if (c->random)
        config_random_positions(m, c->seed, x);
    else
        for (int i = 0; i < n; i++)
            x[i] = c->x0.count ? c->x0.v[c->x0.count == 1 ? 0 : i] : 0.0;
    for (int i = 0; i < n; i++)
        v[i] = c->v0.count ? c->v0.v[c->v0.count == 1 ? 0 : i] : 0.0;
}
