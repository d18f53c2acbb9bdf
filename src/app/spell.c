/* spell.c: the ASCII spellings of the program's own non-ASCII characters. */
#include "spell.h"

#include <string.h>

static const char *const fancy[][2] = {
    {"◆", "*"}, {"■", "#"}, {"┃", "|"}, {"┊", ":"}, {"━", "-"}, {"┅", ":"}, {"┄", "~"}, {"–", "-"},
    {"│", "|"}, {"▸", ">"}, {"×", "x"}, {"·", "."}, {"²", "^2"}, {"←", "Left"},
    {"→", "Right"}, {"↑", "Up"}, {"↓", "Down"}, {"●", "o"}, {"…", "..."}, {"▲", "^"},
    {"▼", "v"}, {"−", "-"}, {"ζ", "zeta"}, {"∞", "inf"}, {"Δ", "d"}, {"δ", "delta"},
    {"π", "pi"}, {"√", "sqrt"}, {"ω", "w"},
};

const char *spell_ascii(const char *s, size_t *len)
{
    for (size_t f = 0; f < sizeof fancy / sizeof *fancy; f++) {
        size_t n = strlen(fancy[f][0]);
        if (strncmp(s, fancy[f][0], n) == 0) {
            *len = n;
            return fancy[f][1];
        }
    }
    return NULL;
}
