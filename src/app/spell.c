/* spell.c: the ASCII spellings of the program's own non-ASCII characters. */
#include "spell.h"

#include <ctype.h>
#include <stdio.h>
#include <string.h>

static const char *const fancy[][2] = {
    {"◆", "*"}, {"■", "#"}, {"┃", "|"}, {"┊", ":"}, {"━", "-"}, {"┅", ":"}, {"┄", "~"}, {"–", "-"},
    {"│", "|"}, {"▸", ">"}, {"×", "x"}, {"·", "."}, {"²", "^2"}, {"←", "Left"},
    {"→", "Right"}, {"↑", "Up"}, {"↓", "Down"}, {"●", "o"}, {"…", "..."}, {"▲", "^"},
    {"▼", "v"}, {"−", "-"}, {"ζ", "zeta"}, {"∞", "inf"}, {"Δ", "d"}, {"δ", "delta"},
    {"π", "pi"}, {"√", "sqrt"}, {"ω", "w"},
};

/* The root sign before a bare number or name ("√20", "√2 f_n") takes its operand in
 * brackets, "sqrt(20)": "sqrt20" reads as a word. */
static const char *root(const char *s, size_t *len)
{
    static char out[32];
    size_t sign = strlen("√"), k = sign;
    while (k - sign < 16 && (isalnum((unsigned char)s[k]) || s[k] == '.' || s[k] == '_'))
        k++;
    if (k == sign)
        return NULL;
    snprintf(out, sizeof out, "sqrt(%.*s)", (int)(k - sign), s + sign);
    *len = k;
    return out;
}

const char *spell_ascii(const char *s, size_t *len)
{
    if (strncmp(s, "√", strlen("√")) == 0) {
        const char *r = root(s, len);
        if (r)
            return r;
    }
    for (size_t f = 0; f < sizeof fancy / sizeof *fancy; f++) {
        size_t n = strlen(fancy[f][0]);
        if (strncmp(s, fancy[f][0], n) == 0) {
            *len = n;
            return fancy[f][1];
        }
    }
    return NULL;
}
