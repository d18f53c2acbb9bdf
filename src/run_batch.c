/* run_batch.c: --batch FILE|-, a parameter study in one process. The file is CSV: a
 * header naming settings (the --summary columns' names: masses,mass,spring,damping,...),
 * then one run per row, each written as the --summary row the same run alone writes,
 * byte for byte, in the rows' order. A bad row is said in one line naming it and the
 * study goes on; the header is written again wherever the number of masses changes. */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "core/config.h"
#include "options.h"
#include "run.h"
#include "run_files.h"

#define BATCH_MAX_COLUMNS CFG_KEY_COUNT

/* The input: where it comes from, the columns its header names. */
struct batch {
    FILE *in;
    const char *name;              /* the file's name as messages say it */
    char *line;                    /* getline's buffer */
    size_t size;                   /* its size */
    long lineno;                   /* the line just read (the header is line 1) */
    int columns;                   /* fields in a row */
    int key[BATCH_MAX_COLUMNS];    /* the setting each column gives */
    char *field[BATCH_MAX_COLUMNS]; /* the row's fields, inside line */
};

/* Whether a row may give setting k: the chain, its drive and its start (what a preset's
 * [system], [motor] and [initial] sections hold) and the run's duration. The series'
 * settings (--sample, --energy) have no place in a summary, the terminal's none here. */
static bool batch_setting(int k)
{
    const char *section = config_options[k].section;
    return k == CFG_DURATION || (section && strcmp(section, "run") != 0);
}

/* Reads the next line without its line end into b->line: its length, or -1 at the end
 * of the input. */
static long next_line(struct batch *b)
{
    ssize_t len = getline(&b->line, &b->size, b->in);
    if (len < 0)
        return -1;
    b->lineno++;
    while (len > 0 && (b->line[len - 1] == '\n' || b->line[len - 1] == '\r'))
        b->line[--len] = '\0';
    return (long)len;
}

/* Splits b->line into fields at commas, in place: a field in double quotes may hold
 * commas (a list, as --summary writes it) and "" for a quote. The number of fields, or
 * -1 with the reason in why (an unclosed quote, too many fields). */
static int split(struct batch *b, const char **why)
{
    char *p = b->line;
    int count = 0;
    for (;;) {
        if (count == BATCH_MAX_COLUMNS) {
            *why = "has more fields than there are settings";
            return -1;
        }
        char *out = p;
        b->field[count++] = out;
        if (*p == '"') {
            for (p++;; p++) {
                if (*p == '\0') {
                    *why = "has a quote that is not closed";
                    return -1;
                }
                if (*p == '"' && p[1] != '"')
                    break;
                if (*p == '"')
                    p++;
                *out++ = *p;
            }
            p++;
            if (*p != ',' && *p != '\0') {
                *why = "has text after a closing quote";
                return -1;
            }
        } else {
            while (*p != ',' && *p != '\0')
                *out++ = *p++;
        }
        char end = *p;
        *out = '\0';
        if (end == '\0')
            return count;
        p++;
    }
}

/* Reads the header: each field the name of a setting a row may give, once. EXIT_SUCCESS,
 * or EXIT_USAGE after one line saying what is wrong and what is allowed. */
static int read_header(struct batch *b)
{
    const char *why = NULL;
    if (next_line(b) < 0) {
        options_say("%s: empty (expected a header naming settings, e.g. "
                    "masses,damping,frequency, then one row per run)", b->name);
        return EXIT_USAGE;
    }
    int n = split(b, &why);
    if (n < 0) {
        options_say("%s:1: the header %s", b->name, why);
        return EXIT_USAGE;
    }
    for (int i = 0; i < n; i++) {
        int k = config_find(b->field[i]);
        char q[4 * CONFIG_QUOTE_MAX + 48];
        config_quote(b->field[i], strlen(b->field[i]), q, sizeof q);
        if (k < 0 || !batch_setting(k)) {
            char allowed[1024] = "";
            for (int j = 0; j < CFG_KEY_COUNT; j++)
                if (batch_setting(j))
                    snprintf(allowed + strlen(allowed), sizeof allowed - strlen(allowed),
                             "%s%s", allowed[0] ? ", " : "", config_options[j].name);
            options_say("%s:1: column %d, %s, is not a setting a run can give (expected "
                        "some of %s)", b->name, i + 1, q, allowed);
            return EXIT_USAGE;
        }
        for (int j = 0; j < i; j++)
            if (b->key[j] == k) {
                options_say("%s:1: column %d, %s, names the same setting as column %d "
                            "(expected each setting once)", b->name, i + 1, q, j + 1);
                return EXIT_USAGE;
            }
        b->key[i] = k;
    }
    b->columns = n;
    return EXIT_SUCCESS;
}

/* The run of the row just read, on top of base: its summary row written to fp (after
 * the header when *header_n is not its number of masses). Returns EXIT_SUCCESS, or
 * EXIT_FAILURE after saying what was wrong (every line prefixed with the row). */
static int run_row(struct batch *b, const struct config *base, FILE *fp, int *header_n)
{
    static struct config c; /* large: lists of up to 1001 values */
    const char *why = NULL;
    char err[512];
    int n = split(b, &why);
    if (n < 0) {
        options_say("%s", why);
        return EXIT_FAILURE;
    }
    if (n != b->columns) {
        options_say("has %d field%s, but the header names %d settings", n, n == 1 ? "" : "s",
                    b->columns);
        return EXIT_FAILURE;
    }
    memcpy(&c, base, sizeof c);
    for (int i = 0; i < n; i++) {
        int k = b->key[i];
        if (b->field[i][0] == '\0')
            continue; /* an empty field: the command line's (or the default) */
        if (config_set(&c, k, b->field[i], err, sizeof err) != 0) {
            options_say("%s: %s", config_options[k].name, err);
            return EXIT_FAILURE;
        }
        c.origin[k] = (struct config_origin){NULL, 0};
    }
    int bad_key;
    struct model *m = config_model(&c, &bad_key, err, sizeof err);
    if (m && ((bad_key = config_check_steps(&c, err, sizeof err)) >= 0 ||
              (bad_key = config_check_exact(&c, err, sizeof err)) >= 0)) {
        model_free(m);
        m = NULL;
    }
    if (!m) {
        /* A setting the row gave is named as its column (as a refused field is); one the
         * command line or a preset gave, as there. */
        int col = b->columns;
        for (int i = 0; bad_key >= 0 && i < n; i++)
            if (b->key[i] == bad_key && b->field[i][0] != '\0')
                col = i;
        if (bad_key < 0)
            options_say("%s", err);
        else if (col < b->columns)
            options_say("%s: %s", config_options[bad_key].name, err);
        else
            options_report_key(&c, bad_key, err);
        return EXIT_FAILURE;
    }
    if (c.random && !c.seed_set) {
        c.seed = ((uint64_t)time(NULL) ^ ((uint64_t)getpid() << 32)) + (uint64_t)b->lineno;
        options_say("--random: seed %llu (--seed %llu repeats this run)",
                    (unsigned long long)c.seed, (unsigned long long)c.seed);
    }
    int status = run_summary(&c, m, fp, *header_n != m->n);
    if (status == EXIT_SUCCESS)
        *header_n = m->n;
    model_free(m);
    return status;
}

int run_batch(const struct config *base, const char *path)
{
    struct batch b = {.name = path};
    bool std = strcmp(path, "-") == 0;
    if (std) {
        b.in = stdin;
        b.name = "standard input";
    } else if (!(b.in = fopen(path, "r"))) {
        options_say("%s: %s", path, strerror(errno));
        return EXIT_FAILURE;
    }
    int status = read_header(&b);
    struct output o = {0};
    if (status == EXIT_SUCCESS && run_open_output(&o, base))
        status = EXIT_FAILURE;
    int header_n = 0; /* the masses of the header last written */
    bool bad = false;
    while (status == EXIT_SUCCESS && next_line(&b) >= 0) {
        if (b.line[0] == '\0')
            continue;
        char where[64 + PATH_MAX];
        snprintf(where, sizeof where, "%s:%ld", b.name, b.lineno);
        options_set_context(where);
        bad |= run_row(&b, base, o.fp, &header_n) != EXIT_SUCCESS;
        options_set_context(NULL);
        if (ferror(o.fp))
            break;
    }
    if (status == EXIT_SUCCESS && ferror(b.in)) {
        options_say("%s: %s", b.name, strerror(errno));
        bad = true;
    }
    if (o.fp)
        status = run_close_output(&o, base, status);
    if (!std)
        fclose(b.in);
    free(b.line);
    return status == EXIT_SUCCESS && bad ? EXIT_FAILURE : status;
}
