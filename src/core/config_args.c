/* config_args.c: a configuration written back as the command line that makes it again:
 * every setting of the table (the rows with a preset section) in the table's order, numbers
 * with the digits that read back exactly. For --meta's comment line, which says how a CSV
 * was made; the preset and output options are not settings of the run. */
#include "config.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void config_format_exact(double v, char *buf, size_t len)
{
    /* A subnormal number from one digit, the shortest (1e-320, not 9.99989e-321); any
     * other from six (10, not 1e+01). */
    for (int digits = fpclassify(v) == FP_SUBNORMAL ? 1 : 6; digits <= 17; digits++) {
        snprintf(buf, len, "%.*g", digits, v);
        if (strtod(buf, NULL) == v)
            return;
    }
}

/* A text value as a shell reads it back: bare when it is made of safe characters,
 * otherwise in single quotes (control bytes escaped, so the line stays one line). */
static void write_text(FILE *out, const char *s)
{
    if (*s && strspn(s, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
                        "+-_.,:/=@%") == strlen(s)) {
        fputs(s, out);
        return;
    }
    char safe[4 * 1024 + 8];
    config_escape(s, strlen(s), 1024, safe, sizeof safe);
    fputc('\'', out);
    for (const char *p = safe; *p; p++)
        fputs(*p == '\'' ? "'\\''" : (char[]){*p, '\0'}, out);
    fputc('\'', out);
}

static void write_number(FILE *out, double v)
{
    char num[32];
    config_format_exact(v, num, sizeof num);
    fputs(num, out);
}

int config_write_args(FILE *out, const struct config *c)
{
    for (int k = 0; k < CFG_KEY_COUNT; k++) {
        const struct config_option *o = &config_options[k];
        const char *at = (const char *)c + o->offset;
        if (!o->section)
            continue;
        switch (o->kind) {
        case CONFIG_FLAG:
            if (*(const bool *)at)
                fprintf(out, " --%s", o->name);
            break;
        case CONFIG_WHOLE:
            if (k == CFG_SEED) {
                /* The seed matters only to random positions; it is said whenever given. */
                if (c->random || c->seed_set)
                    fprintf(out, " --seed %llu", (unsigned long long)c->seed);
            } else {
                fprintf(out, " --%s %d", o->name, *(const int *)at);
            }
            break;
        case CONFIG_NUMBER:
            /* A default said in words ("every step") is no value one can type. */
            if (o->def_text && *(const double *)at == o->def)
                break;
            fprintf(out, " --%s ", o->name);
            write_number(out, *(const double *)at);
            break;
        case CONFIG_LIST: {
            const struct config_list *l = (const struct config_list *)at;
            /* A list never set stands for its default, one value for all. */
            if (l->count == 0 && k == CFG_X0 && c->random)
                break; /* random positions instead */
            fprintf(out, " --%s ", o->name);
            if (l->count == 0)
                write_number(out, o->def);
            for (int i = 0; i < l->count; i++) {
                if (i)
                    fputc(',', out);
                write_number(out, l->v[i]);
            }
            break;
        }
        case CONFIG_CHOICE: {
            int i;
            memcpy(&i, at, sizeof i);
            fprintf(out, " --%s %s", o->name, o->choice_name(i));
            break;
        }
        case CONFIG_TEXT: {
            if (k == CFG_START_MODE) {
                /* Read into a mode and an amplitude; written after x0 and v0, so it wins
                 * over them as it did. */
                if (c->start_mode > 0) {
                    fprintf(out, " --start-mode %d:", c->start_mode);
                    write_number(out, c->start_amp);
                }
                break;
            }
            const char *s;
            memcpy(&s, at, sizeof s);
            if (s) {
                fprintf(out, " --%s ", o->name);
                write_text(out, s);
            }
            break;
        }
        case CONFIG_MODE:
            break;
        }
    }
    return ferror(out) ? -1 : 0;
}
