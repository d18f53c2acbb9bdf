/* preset_save.c: writing a configuration back as a preset file, in the format
 * preset.c reads: every row of the settings table marked saved and in force, in its
 * section, sections and rows in the table's order, each value read through config_get;
 * numbers with the digits that read back exactly, long lists on indented lines. */
#include "preset.h"

#include <string.h>

/* key = list, one value if all are equal, long lists wrapped onto indented lines. */
static void write_list(FILE *out, const char *key, const double *v, int n)
{
    int same = 1;
    for (int i = 1; i < n; i++)
        same &= v[i] == v[0];
    int col = fprintf(out, "%s =", key);
    for (int i = 0; i < (same ? 1 : n); i++) {
        char num[32];
        config_format_exact(v[i], num, sizeof num);
        if (col + (int)strlen(num) + 2 > 78) {
            fputs(i ? ",\n   " : "\n   ", out);
            col = 3;
        } else if (i) {
            fputc(',', out);
            col++;
        }
        col += fprintf(out, " %s", num);
    }
    fputc('\n', out);
}

/* Whether a row before key's has the same section (it was written with that one). */
static bool section_seen(int key)
{
    for (int k = 0; k < key; k++)
        if (config_options[k].saved &&
            strcmp(config_options[k].section, config_options[key].section) == 0)
            return true;
    return false;
}

int preset_write(FILE *out, const struct config *c, const struct model *m)
{
    fprintf(out, "; springsim preset\n[preset]\n");
    if (c->name[0])
        fprintf(out, "name = %s\n", c->name);
    if (c->description[0])
        fprintf(out, "description = %s\n", c->description);
    for (int s = 0; s < CFG_KEY_COUNT; s++) {
        if (!config_options[s].saved || section_seen(s))
            continue;
        const char *section = config_options[s].section;
        fprintf(out, "\n[%s]\n", section);
        for (int k = s; k < CFG_KEY_COUNT; k++) {
            const struct config_option *o = &config_options[k];
            if (!o->saved || strcmp(o->section, section) != 0 || !config_in_force(k, c))
                continue;
            struct config_value v;
            config_get(k, c, m, &v);
            if (v.count)
                write_list(out, o->name, v.v, v.count);
            else
                fprintf(out, "%s = %s\n", o->name, v.str);
        }
    }
    return ferror(out) ? -1 : 0;
}
