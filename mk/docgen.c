/* mk/docgen.c: the options as the README and the man page show them, written from the
 * one option table (core/config.c) that --help and the completions are made from, so
 * that no option, range or default is written by hand. A build tool linked with the core
 * library; mk/docs.sh puts its output between the documents' markers (`make docs`).
 *
 *     docgen names              the long names, one a line, in the table's order
 *     docgen md-options         a Markdown table of every option
 *     docgen man-option NAME    the head of one option's man page entry (.TP, the
 *                               spelling, what it does with its range and default, and
 *                               the preset section it can also be given in)
 *     docgen man-preset-keys    each preset section with its keys, in the table's order
 */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/config.h"

/* s in roff: backslashes and minus signs escaped, a leading dot or quote guarded. */
static void roff(FILE *out, const char *s)
{
    if (*s == '.' || *s == '\'')
        fputs("\\&", out);
    for (; *s; s++) {
        if (*s == '\\')
            fputs("\\e", out);
        else if (*s == '-')
            fputs("\\-", out);
        else
            fputc(*s, out);
    }
}

/* s in a Markdown table cell: | escaped. */
static void md(FILE *out, const char *s)
{
    for (; *s; s++) {
        if (*s == '|')
            fputc('\\', out);
        fputc(*s, out);
    }
}

static void md_options(FILE *out)
{
    fputs("| option | what it sets (range; default) |\n| --- | --- |\n", out);
    for (int k = 0; k < CFG_KEY_COUNT; k++) {
        const struct config_option *o = &config_options[k];
        char arg[128], help[256];
        config_arg(k, arg, sizeof arg);
        config_help(k, help, sizeof help);
        fputs("| ", out);
        if (o->short_name)
            fprintf(out, "`-%c`, ", o->short_name);
        fprintf(out, "`--%s", o->name);
        if (arg[0]) {
            fputc(' ', out);
            md(out, arg);
        }
        fputs("` | ", out);
        md(out, help);
        fputs(" |\n", out);
    }
}

static void man_option(FILE *out, int k)
{
    const struct config_option *o = &config_options[k];
    char arg[128], help[256];
    config_arg(k, arg, sizeof arg);
    config_help(k, help, sizeof help);
    fputs(".TP\n", out);
    if (o->short_name)
        fprintf(out, "\\fB\\-%c\\fR, ", o->short_name);
    fputs("\\fB\\-\\-", out);
    roff(out, o->name);
    fputs("\\fR", out);
    if (arg[0]) {
        /* A choice's names are typed as they are (bold); other arguments are
         * placeholders (italic), | between alternatives upright. */
        const char *face = o->kind == CONFIG_CHOICE ? "\\fB" : "\\fI";
        fprintf(out, " %s", face);
        for (const char *s = arg; *s; s++) {
            if (*s == '|')
                fprintf(out, "\\fR|%s", face);
            else if (*s == '[' || *s == ']')
                fprintf(out, "\\fR%c%s", *s, face);
            else if (*s == '-')
                fputs("\\-", out);
            else
                fputc(*s, out);
        }
        fputs("\\fR", out);
    }
    fputc('\n', out);
    /* The help line starts with a capital in the man page, and ends with a stop. */
    if (help[0] >= 'a' && help[0] <= 'z')
        help[0] = (char)(help[0] - 'a' + 'A');
    roff(out, help);
    fputs(".\n", out);
    if (o->section) {
        fputs("Preset key \\fB", out);
        roff(out, o->name);
        fprintf(out, "\\fR in [%s].\n", o->section);
    }
}

/* Each section the rows name, in the order they first name it, with its keys. */
static void man_preset_keys(FILE *out)
{
    for (int k = 0; k < CFG_KEY_COUNT; k++) {
        const char *sec = config_options[k].section;
        bool first = sec != NULL;
        for (int j = 0; j < k && first; j++)
            if (config_options[j].section && strcmp(config_options[j].section, sec) == 0)
                first = false;
        if (!first)
            continue;
        fprintf(out, ".TP\n.B [%s]\n", sec);
        int last = k;
        for (int j = k; j < CFG_KEY_COUNT; j++)
            if (config_options[j].section && strcmp(config_options[j].section, sec) == 0)
                last = j;
        for (int j = k; j <= last; j++) {
            if (!config_options[j].section || strcmp(config_options[j].section, sec) != 0)
                continue;
            fputs(j == last ? ".B " : ".BR ", out);
            roff(out, config_options[j].name);
            fputs(j == last ? "\n" : " ,\n", out);
        }
    }
}

int main(int argc, char **argv)
{
    if (argc == 2 && strcmp(argv[1], "names") == 0) {
        for (int k = 0; k < CFG_KEY_COUNT; k++)
            printf("%s\n", config_options[k].name);
    } else if (argc == 2 && strcmp(argv[1], "md-options") == 0) {
        md_options(stdout);
    } else if (argc == 2 && strcmp(argv[1], "man-preset-keys") == 0) {
        man_preset_keys(stdout);
    } else if (argc == 3 && strcmp(argv[1], "man-option") == 0) {
        int k = config_find(argv[2]);
        if (k < 0) {
            fprintf(stderr, "docgen: no option '%s' in the table\n", argv[2]);
            return 2;
        }
        man_option(stdout, k);
    } else {
        fputs("usage: docgen names | md-options | man-preset-keys | man-option NAME\n", stderr);
        return 2;
    }
    return fflush(stdout) == 0 && !ferror(stdout) ? 0 : 1;
}
