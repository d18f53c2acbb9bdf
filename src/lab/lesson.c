/* lesson.c: lesson files read and checked line by line, and found on the search path.
 * Every line is one item: `title`, `say`, a command of the plain mode, `pause`, `ask`
 * followed by its `choice` lines and perhaps an `answer`, a `setup` ... `end` block
 * holding a preset's text, `expect`; `#` starts a comment line. */
#include "lesson.h"

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../core/lines.h"
#include "../core/search.h"
#include "../app/command.h"

struct reader {
    struct lesson *l;
    const char *path;
    int line;
    char *err;
    size_t errlen;
    int cap;       /* items room */
    int ask;       /* the question taking choices, or -1 */
    bool answered; /* it has its answer line */
    int commands;  /* commands and setups so far */
    size_t said;   /* bytes of the step's caption so far */
};

static int bad(struct reader *r, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static int bad(struct reader *r, const char *fmt, ...)
{
    char what[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    snprintf(r->err, r->errlen, "%s:%d: %s", r->path, r->line, what);
    return 2;
}

static struct lesson_item *add(struct reader *r, enum lesson_kind kind, const char *text)
{
    struct lesson *l = r->l;
    if (l->count == r->cap) {
        int cap = r->cap ? 2 * r->cap : 32;
        struct lesson_item *more = realloc(l->items, (size_t)cap * sizeof *more);
        if (!more)
            return NULL;
        l->items = more;
        r->cap = cap;
    }
    struct lesson_item *it = &l->items[l->count];
    memset(it, 0, sizeof *it);
    it->kind = kind;
    it->line = r->line;
    it->text = strdup(text);
    if (!it->text)
        return NULL;
    l->count++;
    return it;
}

/* A question whose choices are over: it needs two at least. */
static int close_ask(struct reader *r)
{
    if (r->ask < 0)
        return 0;
    const struct lesson_item *q = &r->l->items[r->ask];
    r->ask = -1;
    if (q->nchoices < 2) {
        r->line = q->line;
        return bad(r, "ask needs two choices at least, each on a 'choice TEXT' line after it");
    }
    return 0;
}

/* One line (NUL-terminated, its end of line gone). */
/* A question's choice line: its text added to the question being asked. */
static int word_choice(struct reader *r, char *rest)
{
    struct lesson_item *q = &r->l->items[r->ask];
    if (r->answered)
        return bad(r, "a choice after the answer line (the choices come first)");
    if (!*rest)
        return bad(r, "choice needs its text");
    if (q->nchoices == LESSON_MAX_CHOICES)
        return bad(r, "a question has %d choices at most", LESSON_MAX_CHOICES);
    if (!(q->choice[q->nchoices] = strdup(rest)))
        return 1;
    q->nchoices++;
    return 0;
}

/* A question's answer line: which of its choices is right. */
static int word_answer(struct reader *r, char *rest)
{
    struct lesson_item *q = &r->l->items[r->ask];
    int k = lesson_choice(q, rest);
    if (r->answered)
        return bad(r, "the question has its answer already");
    if (!k)
        return bad(r, "answer: '%.40s' is not one of the %d choices above (expected 1 to %d)",
                   rest, q->nchoices, q->nchoices);
    q->answer = k;
    r->answered = true;
    return 0;
}

static int word_title(struct reader *r, char *rest)
{
    if (r->l->title[0])
        return bad(r, "a second title line (a lesson has one)");
    if (!*rest)
        return bad(r, "title needs its text");
    snprintf(r->l->title, sizeof r->l->title, "%s", rest);
    return 0;
}

static int word_say(struct reader *r, char *rest)
{
    r->said += strlen(rest) + 1;
    if (r->said >= LESSON_CAPTION)
        return bad(r, "the step's say lines come to more than %d bytes here (a caption is a "
                   "paragraph: end the step with pause, or say less)", LESSON_CAPTION - 1);
    return add(r, LESSON_SAY, rest) ? 0 : 1;
}

static int word_pause(struct reader *r, char *rest)
{
    r->said = 0;
    if (*rest)
        return bad(r, "pause takes nothing, but was given '%.40s'", rest);
    r->l->steps++;
    return add(r, LESSON_PAUSE, "") ? 0 : 1;
}

static int word_ask(struct reader *r, char *rest)
{
    r->said = 0;
    if (!*rest)
        return bad(r, "ask needs its question");
    if (!add(r, LESSON_ASK, rest))
        return 1;
    r->l->steps++;
    r->ask = r->l->count - 1;
    r->answered = false;
    return 0;
}

/* Whether text is a state as lesson_state writes it: t=T, then xI=X vI=V for I = 1, 2, ...,
 * each value a finite number (strtod's, %a's hexadecimal included). A state of other
 * masses than the chain's is well formed, only not the one reached: the replay says so. */
static bool state_line(const char *text)
{
    const char *p = text;
    for (int k = 0;; k++) {
        char name[16];
        if (k == 0)
            snprintf(name, sizeof name, "t=");
        else
            snprintf(name, sizeof name, "%c%d=", k % 2 ? 'x' : 'v', (k + 1) / 2);
        size_t len = strlen(name);
        if (strncmp(p, name, len) != 0)
            return false;
        char *end;
        double value = strtod(p + len, &end);
        if (end == p + len || (*end != ' ' && *end != '\0') || !isfinite(value))
            return false;
        if (*end == '\0')
            return k % 2 == 0; /* each mass named with its x and v */
        p = end + 1;
    }
}

static int word_expect(struct reader *r, char *rest)
{
    if (!state_line(rest))
        return bad(r, "expect: '%.40s' is not a state (expected 't=T x1=X v1=V ...' as --record "
                   "writes it)", rest);
    return add(r, LESSON_EXPECT, rest) ? 0 : 1;
}

static int word_wait(struct reader *r, char *rest)
{
    double sec = 0.0;
    const char *why = config_parse_number(rest, &sec);
    if (why || !(sec > 0.0 && sec <= LESSON_MAX_WAIT))
        return bad(r, "wait: '%.40s' %s (expected 0 < SECONDS <= %g, the wall-clock time the "
                   "program waits)", rest, why ? why : "is out of range", LESSON_MAX_WAIT);
    struct lesson_item *it = add(r, LESSON_WAIT, rest);
    if (!it)
        return 1;
    it->value = sec;
    return 0;
}

/* The playback speed of the runs that follow: the Speed control, as set sets it (the dry
 * run says what is wrong with the number). */
static int word_speed(struct reader *r, char *rest)
{
    char line[LESSON_MAX_LINE + 16];
    if (!*rest)
        return bad(r, "speed needs a number (the playback speed, 0.1 to 10)");
    snprintf(line, sizeof line, "set speed %s", rest);
    return add(r, LESSON_COMMAND, line) ? 0 : 1;
}

static int word_end(struct reader *r, char *rest)
{
    (void)rest;
    return bad(r, "end without a setup line before it");
}

static int word_setup(struct reader *r, char *rest)
{
    (void)rest;
    return bad(r, "setup needs its 'end' line");
}

/* A lesson's own words (beside the plain mode's commands), each read by its function. */
static const struct {
    const char *word;
    int (*read)(struct reader *r, char *rest);
} lesson_words[] = {
    {"title", word_title}, {"say", word_say},     {"pause", word_pause},
    {"ask", word_ask},     {"expect", word_expect}, {"wait", word_wait},
    {"speed", word_speed}, {"end", word_end},     {"setup", word_setup},
};

/* A command of the plain mode in a lesson: allowed there, within the lesson's time, after
 * its preset; kept as written, its blanks made one. */
static int command_line(struct reader *r, const char *word, size_t wlen, const char *rest)
{
    const struct command *cmd = command_find(word, wlen);
    if (!cmd)
        return bad(r, "'%.*s' is not a command or a lesson's word (expected title, say, pause, "
                   "ask, choice, answer, setup, expect or a command of the plain mode: help "
                   "lists them)", wlen > 40 ? 40 : (int)wlen, word);
    if (cmd->flags & COMMAND_NOT_IN_LESSON)
        return bad(r, "%s is not allowed in a lesson (it %s)", cmd->name,
                   cmd->flags & COMMAND_ENDS ? "would end the program" : "writes a file");
    double sec = 0.0; /* a run's own errors are the dry run's to say */
    if ((cmd->flags & COMMAND_RUNS) && config_parse_number(rest, &sec) == NULL && sec > 0.0) {
        r->l->seconds += sec;
        if (r->l->seconds > LESSON_MAX_SECONDS)
            return bad(r, "run %.40s: the lesson's runs come to %.10g s of simulated time "
                       "here, past the %.0f s (30 minutes) a lesson may run", rest,
                       r->l->seconds, LESSON_MAX_SECONDS);
    }
    if (r->commands++ == 0 && !(cmd->flags & COMMAND_LOADS))
        return bad(r, "a lesson starts from a known chain: its first command is 'preset NAME' "
                   "(or a setup block), not %s", cmd->name);
    char line[LESSON_MAX_LINE + 2];
    snprintf(line, sizeof line, "%.*s%s%s", (int)wlen, word, *rest ? " " : "", rest);
    return add(r, LESSON_COMMAND, line) ? 0 : 1;
}

static int read_line(struct reader *r, char *s)
{
    for (const char *c = s; *c; c++)
        if ((unsigned char)*c < 0x20 && *c != '\t')
            return bad(r, "a control character (\\x%02x) in the text (a lesson is plain text)",
                       (unsigned char)*c);
    char *word = s + strspn(s, " \t");
    char *rest = word + strcspn(word, " \t");
    size_t wlen = (size_t)(rest - word);
    rest += strspn(rest, " \t");
    for (char *e = rest + strlen(rest); e > rest && (e[-1] == ' ' || e[-1] == '\t');)
        *--e = '\0';
    if (!*word || *word == '#')
        return 0;
#define IS(w) (wlen == strlen(w) && strncmp(word, w, wlen) == 0)
    if (r->ask >= 0 && IS("choice"))
        return word_choice(r, rest);
    if (r->ask >= 0 && IS("answer"))
        return word_answer(r, rest);
    int st = close_ask(r);
    if (st)
        return st;
    if (IS("choice") || IS("answer"))
        return bad(r, "%.*s outside a question (it follows an 'ask' line)", (int)wlen, word);
    for (size_t i = 0; i < sizeof lesson_words / sizeof *lesson_words; i++)
        if (IS(lesson_words[i].word))
            return lesson_words[i].read(r, rest);
#undef IS
    return command_line(r, word, wlen, rest);
}

/* A setup block, from the line after `setup` to its `end`: the preset text, with as many
 * newlines before it as lines before the block, so that its errors name the file's line. */
static int read_setup(struct reader *r, struct lines *in)
{
    int first = r->line;
    size_t cap = (size_t)(in->end - in->s) + (size_t)first + 2;
    char *text = malloc(cap), *o = text;
    if (!text)
        return 1;
    memset(o, '\n', (size_t)first);
    o += first;
    const char *s, *eol;
    /* Every line as it is: the preset's own reading says what is wrong with one. */
    while (lines_next(in, SIZE_MAX, &s, &eol) != LINES_END) {
        r->line = in->line;
        const char *w = s + strspn(s, " \t");
        size_t n = (size_t)(eol - w);
        while (n && (w[n - 1] == ' ' || w[n - 1] == '\t' || w[n - 1] == '\r'))
            n--;
        if (n == 3 && strncmp(w, "end", 3) == 0) {
            *o = '\0';
            struct lesson_item *it = add(r, LESSON_SETUP, text);
            if (it)
                it->line = first;
            free(text);
            r->commands++;
            return it ? 0 : 1;
        }
        memcpy(o, s, (size_t)(eol - s));
        o += eol - s;
        *o++ = '\n';
    }
    free(text);
    r->line = first;
    return bad(r, "setup without its 'end' line");
}

void lesson_free(struct lesson *l)
{
    for (int i = 0; i < l->count; i++) {
        free(l->items[i].text);
        for (int k = 0; k < l->items[i].nchoices; k++)
            free(l->items[i].choice[k]);
    }
    free(l->items);
    l->items = NULL;
    l->count = l->steps = 0;
}

/* The lesson's name: its file's name without .lesson. */
static void name_of(const char *path, char *out, size_t len)
{
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    size_t n = strlen(base), e = strlen(LESSON_EXT);
    if (n > e && strcmp(base + n - e, LESSON_EXT) == 0)
        n -= e;
    snprintf(out, len, "%.*s", (int)n, base);
}

int lesson_read(const char *path, struct lesson *l, char *err, size_t errlen)
{
    char *text;
    size_t size;
    memset(l, 0, sizeof *l);
    snprintf(l->path, sizeof l->path, "%s", path);
    name_of(path, l->name, sizeof l->name);
    int st = search_read(path, LESSON_MAX_BYTES, "a lesson", &text, &size, err, errlen);
    if (st)
        return st;
    struct reader r = {.l = l, .path = path, .err = err, .errlen = errlen, .ask = -1};
    struct lines in = lines_of(text, size);
    const char *from, *to;
    enum lines_status got;
    while (!st && (got = lines_next(&in, LESSON_MAX_LINE, &from, &to)) != LINES_END) {
        r.line = in.line;
        if (got == LINES_NUL) {
            st = bad(&r, "contains a NUL byte (a lesson is text)");
            break;
        }
        if (got == LINES_LONG) {
            st = bad(&r, "line is longer than %d characters", LESSON_MAX_LINE);
            break;
        }
        /* The text is the reader's own copy: each line is cut out of it in place. */
        char *line = text + (from - text), *eol = text + (to - text);
        if (eol > line && eol[-1] == '\r')
            eol[-1] = '\0';
        *eol = '\0';
        char *w = line + strspn(line, " \t");
        if (strcmp(w, "setup") == 0 || strncmp(w, "setup ", 6) == 0 ||
            strncmp(w, "setup\t", 6) == 0) {
            st = close_ask(&r);
            if (!st && w[5] && w[5 + strspn(w + 5, " \t")])
                st = bad(&r, "setup takes nothing on its line (the preset's lines follow, "
                         "then 'end')");
            if (!st)
                st = read_setup(&r, &in);
            continue;
        }
        st = read_line(&r, w);
    }
    if (!st)
        st = close_ask(&r);
    if (!st && !l->title[0]) {
        r.line = 1;
        st = bad(&r, "no title line (expected 'title TEXT', the lesson's name in the menu)");
    }
    if (!st && r.commands == 0) {
        r.line = r.line ? r.line : 1;
        st = bad(&r, "no command (a lesson starts with 'preset NAME')");
    }
    free(text);
    if (st == 1 && !err[0])
        snprintf(err, errlen, "%s: out of memory", path);
    if (st)
        lesson_free(l);
    return st;
}

int lesson_choice(const struct lesson_item *ask, const char *text)
{
    const char *s = text + strspn(text, " \t");
    size_t n = strcspn(s, " \t");
    if (s[n + strspn(s + n, " \t")] != '\0' || n == 0)
        return 0;
    int k = 0;
    if (n == 1 && isalpha((unsigned char)*s))
        k = tolower((unsigned char)*s) - 'a' + 1;
    else if (n == 1 && isdigit((unsigned char)*s))
        k = *s - '0';
    return k >= 1 && k <= ask->nchoices ? k : 0;
}

int lesson_find(const char *name, const char *exe_dir, char *out, size_t len)
{
    size_t n = strlen(name), e = strlen(LESSON_EXT);
    if (strchr(name, '/') || (n > e && strcmp(name + n - e, LESSON_EXT) == 0)) {
        if (n < len) {
            memcpy(out, name, n + 1);
            return 0;
        }
        snprintf(out, len, "'%.36s...' is too long for a file name", name);
        return -1;
    }
    if (n > 0 && n < 200) {
        char dirs[SEARCH_DIRS][SEARCH_DIR_MAX];
        int count = search_dirs(SEARCH_LESSONS, exe_dir, dirs);
        for (int i = 0; i < count; i++) {
            int w = snprintf(out, len, "%s/%s%s", dirs[i], name, LESSON_EXT);
            if (w > 0 && (size_t)w < len && access(out, F_OK) == 0)
                return 0;
        }
    }
    char q[4 * CONFIG_QUOTE_MAX + 48];
    config_quote(name, n, q, sizeof q);
    snprintf(out, len, "%s is not a lesson (expected a name from --list-lessons, or a file)", q);
    return -1;
}

static void find_title(const char *text, char *title, size_t len)
{
    title[0] = '\0';
    for (const char *s = text; *s;) {
        s += strspn(s, " \t");
        size_t n = strcspn(s, "\n");
        if (strncmp(s, "title", 5) == 0 && (s[5] == ' ' || s[5] == '\t')) {
            const char *t = s + 5 + strspn(s + 5, " \t");
            size_t m = (size_t)(s + n - t);
            while (m && (t[m - 1] == '\r' || t[m - 1] == ' '))
                m--;
            snprintf(title, len, "%.*s", (int)m, t);
            for (char *c = title; *c; c++)
                if ((unsigned char)*c < 0x20)
                    *c = ' ';
            return;
        }
        s += n + (s[n] == '\n');
    }
}

int lesson_scan(const char *exe_dir, struct search_entry **out)
{
    return search_scan(SEARCH_LESSONS, exe_dir, LESSON_MAX_BYTES, find_title, out);
}
