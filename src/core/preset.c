/* preset.c: INI presets. libinih does the parsing; a first pass over the text checks
 * what inih cannot report well or lets through (long lines, NUL bytes, unknown sections,
 * text after a section header, keys given twice) and tells which line each handler call
 * comes from, so every error names its file and line. A lone CR ends a line. A key's value may go on over indented continuation lines, which is
 * how long lists are written back. */
#include "preset.h"

#include <errno.h>
#include <stdbool.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <ini.h>

#include "lines.h"
#include "search.h"

#ifndef PRESETDIR
#define PRESETDIR "/usr/local/share/springsim/presets"
#endif

const char preset_installed_dir[] = PRESETDIR;

static const char *const sections[] = {"preset", "system", "motor", "initial", "run"};

struct parse {
    const char *path;     /* for messages and origins */
    struct config *c;     /* what the preset sets */
    int *lines;           /* line of each handler call, in order */
    char *cont;           /* whether that call is a continuation line of the key before */
    int nlines;           /* handler calls expected */
    int call;             /* handler calls so far */
    char *joined;         /* value of the current key so far, continuations appended */
    size_t joined_cap;    /* bytes in joined */
    int pending;          /* line of a value, empty or ending in ',', awaiting its rest, or 0 */
    int pending_key;      /* its key */
    int err_line;         /* line of the first error the handler found, 0 if none */
    char msg[512];        /* that error */
};

static const char *skip_blank(const char *p, const char *end)
{
    while (p < end && (*p == ' ' || *p == '\t' || *p == '\r'))
        p++;
    return p;
}

static int known_section(const char *s, size_t len)
{
    for (size_t i = 0; i < sizeof sections / sizeof *sections; i++)
        if (strlen(sections[i]) == len && strncmp(s, sections[i], len) == 0)
            return 1;
    return 0;
}

/* Copies a trimmed name [p, q) into buf; returns its length. */
static size_t copy_name(const char *p, const char *q, char *buf, size_t len)
{
    while (q > p && (q[-1] == ' ' || q[-1] == '\t'))
        q--;
    size_t n = (size_t)(q - p);
    if (n >= len)
        n = len - 1;
    memcpy(buf, p, n);
    buf[n] = '\0';
    return n;
}

/* The message for a line over PRESET_MAX_LINE: which key it holds (key, for an indented
 * continuation line, or the name before its '=') and how to write it within the limit. */
static void too_long(struct parse *p, const char *start, const char *eol, const char *key)
{
    char name[64];
    const char *what = "the value";
    if (key) {
        snprintf(name, sizeof name, "%s", key);
        what = "a continuation";
    } else {
        const char *sep = start;
        while (sep < eol && *sep != '=' && *sep != ':' && sep - start < 63)
            sep++;
        if (sep == eol || (*sep != '=' && *sep != ':') || *start == ';' || *start == '#' ||
            *start == '[') {
            snprintf(p->msg, sizeof p->msg, "line is longer than %d characters (the longest "
                     "a preset line may be)", PRESET_MAX_LINE);
            return;
        }
        copy_name(start, sep, name, sizeof name);
    }
    for (char *q = name; *q; q++)
        if (*q < 0x20 || *q > 0x7e)
            *q = '?';
    snprintf(p->msg, sizeof p->msg, "line is longer than %d characters, in %s of '%s' "
             "(a list may go on over indented lines, each ending in ',' but the last; "
             "one value must fit on one line)", PRESET_MAX_LINE, what, name);
}

/* Whether two keys name one setting: the same but for '_' in place of '-' (find_key). */
static bool same_key(const char *a, const char *b)
{
    for (; *a && *b; a++, b++)
        if (*a != *b && !((*a == '_' || *a == '-') && (*b == '_' || *b == '-')))
            return false;
    return *a == *b;
}

/* The first pass: mirrors how inih classifies lines (comment, section, continuation,
 * key) and checks what it cannot. Returns the bad line, or 0 with p->lines filled. */
static int prescan(struct parse *p, const char *text, size_t size)
{
    char seen[64][64];
    int seen_line[64], nseen = 0;
    char key[64];
    int have_key = 0, line;
    struct lines r = lines_of(text, size);
    const char *s, *eol;
    enum lines_status st;

    /* A BOM counts towards the first line's length (inih reads it as part of the line)
     * but not towards what the line says. */
    int bom = size >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0 ? 3 : 0;
    while ((st = lines_next(&r, PRESET_MAX_LINE, &s, &eol)) != LINES_END) {
        line = r.line;
        if (st == LINES_NUL) {
            snprintf(p->msg, sizeof p->msg, "contains a NUL byte (a preset is text)");
            return line;
        }
        const char *start = skip_blank(line == 1 ? s + bom : s, eol);
        if (st == LINES_LONG) {
            too_long(p, start, eol, have_key && start > s ? key : NULL);
            return line;
        }
        if (start == eol || *start == ';' || *start == '#') {
            /* blank or comment */
        } else if (*start == '[') {
            const char *close = memchr(start, ']', (size_t)(eol - start));
            if (!close) {
                snprintf(p->msg, sizeof p->msg, "section has no closing ']'");
                return line;
            }
            const char *after = skip_blank(close + 1, eol);
            if (after < eol && *after != ';' && *after != '#') {
                char name[64];
                copy_name(start + 1, close, name, sizeof name);
                snprintf(p->msg, sizeof p->msg, "text after the section header [%s] (a "
                         "section line holds only '[name]' and perhaps a comment)", name);
                return line;
            }
            if (!known_section(start + 1, (size_t)(close - start - 1))) {
                char name[64];
                copy_name(start + 1, close, name, sizeof name);
                snprintf(p->msg, sizeof p->msg, "unknown section [%s] (expected [preset], "
                         "[system], [motor], [initial] or [run])", name);
                return line;
            }
            have_key = 0; /* keys are unique across sections, so 'seen' goes on */
        } else if (have_key && start > s) {
            p->cont[p->nlines] = 1; /* continuation of the previous key */
            p->lines[p->nlines++] = line;
        } else {
            const char *sep = start;
            while (sep < eol && *sep != '=' && *sep != ':')
                sep++;
            if (sep == eol) {
                snprintf(p->msg, sizeof p->msg, "expected 'key = value', '[section]' or a "
                         "comment");
                return line;
            }
            copy_name(start, sep, key, sizeof key);
            for (int i = 0; i < nseen; i++) {
                if (same_key(seen[i], key)) {
                    if (strcmp(seen[i], key) == 0)
                        snprintf(p->msg, sizeof p->msg, "'%s' is given twice (first on "
                                 "line %d)", key, seen_line[i]);
                    else
                        snprintf(p->msg, sizeof p->msg, "'%s' is given twice (first on "
                                 "line %d, as '%.63s')", key, seen_line[i], seen[i]);
                    return line;
                }
            }
            if (nseen < 64) {
                strcpy(seen[nseen], key);
                seen_line[nseen++] = line;
            }
            have_key = 1;
            p->cont[p->nlines] = 0;
            p->lines[p->nlines++] = line;
        }
    }
    return 0;
}

/* Cuts a '#' comment that follows blanks (inih cuts ';' ones itself). */
static void cut_hash_comment(char *v)
{
    for (char *q = v; *q; q++) {
        if (*q == '#' && (q == v || q[-1] == ' ' || q[-1] == '\t')) {
            *q = '\0';
            break;
        }
    }
    size_t n = strlen(v);
    while (n > 0 && (v[n - 1] == ' ' || v[n - 1] == '\t'))
        v[--n] = '\0';
}

/* Keeps the first error the handler finds; returns 0, inih's "error" answer. */
static int handler_fail(struct parse *p, int line, const char *msg)
{
    if (!p->err_line) {
        p->err_line = line;
        snprintf(p->msg, sizeof p->msg, "%s", msg);
    }
    return 0;
}

/* A value left empty or ending in ',' with no continuation: check it as it stands. */
static int check_pending(struct parse *p)
{
    char why[400], msg[512];
    int key = p->pending_key, line = p->pending;
    p->pending = 0;
    if (config_set(p->c, key, p->joined, why, sizeof why) == 0)
        return 1;
    snprintf(msg, sizeof msg, "%s: %s", config_options[key].name, why);
    return handler_fail(p, line, msg);
}

/* The setting a preset key names: its option's name, or the same with '_' for each '-'
 * (spring_cubic is spring-cubic). */
static int find_key(const char *name)
{
    char dashed[64];
    snprintf(dashed, sizeof dashed, "%s", name);
    for (char *q = dashed; *q; q++)
        if (*q == '_')
            *q = '-';
    return config_find(dashed);
}

static int handler(void *user, const char *section, const char *name, const char *value)
{
    struct parse *p = user;
    int line = p->call < p->nlines ? p->lines[p->call] : 0;
    int continued = p->call < p->nlines && p->cont[p->call];
    p->call++;
    if (p->err_line)
        return 1; /* report the first error only */

    char msg[512];
    if (*name == '\0')
        return handler_fail(p, line, "a key name is missing before '='");
    if (p->pending && !continued && !check_pending(p))
        return 0;
    size_t have = continued ? strlen(p->joined) : 0;
    size_t add = strlen(value);
    if (have + add + 2 > p->joined_cap) {
        snprintf(msg, sizeof msg, "value of '%s' is too long", name);
        return handler_fail(p, line, msg);
    }
    if (continued && have > 0 && p->joined[have - 1] != ',' && add > 0 && value[0] != ',')
        p->joined[have++] = ',';
    memcpy(p->joined + have, value, add + 1);
    cut_hash_comment(p->joined + have);

    if (*section == '\0') {
        snprintf(msg, sizeof msg, "'%s' is outside any section", name);
        return handler_fail(p, line, msg);
    }
    if (strcmp(section, "preset") == 0) {
        if (strcmp(name, "name") == 0)
            snprintf(p->c->name, sizeof p->c->name, "%s", p->joined);
        else if (strcmp(name, "description") == 0)
            snprintf(p->c->description, sizeof p->c->description, "%s", p->joined);
        else {
            snprintf(msg, sizeof msg, "unknown key '%s' in [preset] (expected name or "
                     "description)", name);
            return handler_fail(p, line, msg);
        }
        return 1;
    }
    int key = find_key(name);
    if (key < 0 || !config_options[key].section) {
        snprintf(msg, sizeof msg, "unknown key '%.64s' in [%s]", name, section);
        return handler_fail(p, line, msg);
    }
    if (strcmp(config_options[key].section, section) != 0) {
        snprintf(msg, sizeof msg, "'%s' belongs in [%s], not [%s]", name,
                 config_options[key].section, section);
        return handler_fail(p, line, msg);
    }
    size_t len = strlen(p->joined);
    if (len == 0 || p->joined[len - 1] == ',') {
        /* Empty, or ending in ',': the value may go on over the next, indented line, so it
         * is checked when it is whole. */
        if (!continued)
            p->c->origin[key] = (struct config_origin){p->path, line};
        p->pending = line;
        p->pending_key = key;
        return 1;
    }
    p->pending = 0;
    char why[400];
    if (config_set(p->c, key, p->joined, why, sizeof why) != 0) {
        snprintf(msg, sizeof msg, "%s: %s", name, why);
        return handler_fail(p, line, msg);
    }
    if (!continued)
        p->c->origin[key] = (struct config_origin){p->path, line};
    return 1;
}

/* Reads a whole file of at most PRESET_MAX_BYTES into a NUL-terminated buffer. Only a
 * regular file is read: the open does not wait (a FIFO with no writer would block it),
 * and a device, a FIFO or a file over the limit is refused before any read. */
static enum preset_status slurp(const char *path, char **text, size_t *size, char *err,
                                size_t errlen)
{
    int st = search_read(path, PRESET_MAX_BYTES, "a preset", text, size, err, errlen);
    return st == 0 ? PRESET_OK : st == 2 ? PRESET_BAD : PRESET_IO;
}

enum preset_status preset_load(const char *path, struct config *c, char *err, size_t errlen)
{
    char *text;
    size_t size;
    enum preset_status st = slurp(path, &text, &size, err, errlen);
    if (st != PRESET_OK)
        return st;
    st = preset_parse(path, text, size, c, err, errlen);
    free(text);
    return st;
}

enum preset_status preset_parse(const char *path, const char *text, size_t size,
                                struct config *c, char *err, size_t errlen)
{
    enum preset_status st = PRESET_OK;
    if (size > PRESET_MAX_BYTES) {
        snprintf(err, errlen, "%s: too large for a preset (more than %d bytes)", path,
                 PRESET_MAX_BYTES);
        return PRESET_BAD;
    }
    /* inih reads a NUL-terminated string; a NUL inside is reported by the first pass. */
    char *copy = malloc(size + 1);
    if (!copy) {
        snprintf(err, errlen, "%s: %s", path, strerror(ENOMEM));
        return PRESET_IO;
    }
    memcpy(copy, text, size);
    copy[size] = '\0';
    /* A lone CR (old Mac line endings) ends a line, as it does on the screen; inih splits
     * on LF only and would read the whole file as one line. CR LF stays as it is. */
    for (size_t i = 0; i < size; i++)
        if (copy[i] == '\r' && (i + 1 == size || copy[i + 1] != '\n'))
            copy[i] = '\n';

    struct parse p = {.path = path, .c = c};
    p.lines = malloc((size / 2 + 2) * sizeof *p.lines); /* a value line has 2+ bytes */
    p.cont = malloc(size / 2 + 2);
    p.joined_cap = 2 * size + 64;
    p.joined = calloc(p.joined_cap, 1);
    if (!p.lines || !p.cont || !p.joined) {
        snprintf(err, errlen, "%s: %s", path, strerror(ENOMEM));
        st = PRESET_IO;
        goto out;
    }
    int bad = prescan(&p, copy, size);
    if (!bad) {
        int line = ini_parse_string(copy, handler, &p);
        if (p.pending && !p.err_line)
            check_pending(&p);
        if (line != 0 && line != p.err_line) {
            bad = line;
            snprintf(p.msg, sizeof p.msg, "expected 'key = value', '[section]' or a comment");
        } else {
            bad = p.err_line;
        }
    }
    if (bad) {
        snprintf(err, errlen, "%s:%d: %s", path, bad, p.msg);
        st = PRESET_BAD;
    }
out:
    free(p.lines);
    free(p.cont);
    free(p.joined);
    free(copy);
    return st;
}

int preset_user_dir(char *out, size_t len)
{
    return search_user_dir(SEARCH_PRESETS, out, len);
}

enum preset_status preset_find(const char *name, const char *exe_dir, char *out, size_t len)
{
    size_t n = strlen(name);
    if (strchr(name, '/') || (n > 4 && strcmp(name + n - 4, ".ini") == 0)) {
        /* Never cut: a shortened path could name another file. */
        if (n < len) {
            memcpy(out, name, n + 1);
            return PRESET_OK;
        }
        snprintf(out, len, "'%.36s...' is too long for a file name (%zu bytes; expected at "
                 "most %zu)", name, n, len - 1);
        return PRESET_NONE;
    }
    if (n > 0 && n < 200) {
        char dirs[SEARCH_DIRS][SEARCH_DIR_MAX];
        int count = search_dirs(SEARCH_PRESETS, exe_dir, dirs);
        for (int i = 0; i < count; i++) {
            int w = snprintf(out, len, "%s/%s.ini", dirs[i], name);
            if (w > 0 && (size_t)w < len && access(out, F_OK) == 0)
                return PRESET_OK;
        }
    }
    char q[64];
    snprintf(q, sizeof q, n > 40 ? "'%.36s...'" : "'%s'", name);
    snprintf(out, len, "%s is not a preset (expected a name from --list-presets, or a file)",
             q);
    return PRESET_NONE;
}

/* What preset_scan's about function gives the parser: where the description goes. */
struct about {
    char *text;
    size_t len;
};

static int describe(void *user, const char *section, const char *name, const char *value)
{
    struct about *ab = user;
    /* Escaped here, for every list that shows it (the menu, --list-presets, presets):
     * no control byte, no Unicode format character reaches a screen raw. */
    if (strcmp(section, "preset") == 0 && strcmp(name, "description") == 0)
        config_escape(value, strlen(value), strlen(value), ab->text, ab->len);
    return 1;
}

static void preset_about(const char *text, char *about, size_t len)
{
    ini_parse_string(text, describe, &(struct about){about, len});
}

int preset_scan(const char *exe_dir, struct search_entry **out)
{
    return search_scan(SEARCH_PRESETS, exe_dir, PRESET_MAX_BYTES, preset_about, out);
}

int preset_list(FILE *out, const char *exe_dir)
{
    struct search_entry *all;
    int have = preset_scan(exe_dir, &all);
    search_list(out, all, have, "(no description)");
    free(all);
    return have;
}
