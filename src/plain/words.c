/* words.c: the plain mode's lines made plain (words.h). */
#include "words.h"

#include <stdio.h>
#include <string.h>

#include "../app/spell.h"
#include "../core/config.h"

/* text made safe to print into out: control bytes and invalid UTF-8 escaped, the
 * program's own symbols in ASCII, other UTF-8 kept in a UTF-8 locale and escaped byte by
 * byte in any other. */
void plain_text(const char *text, bool utf8, char *out, size_t len)
{
    char esc[4 * 2048 + 8];
    config_escape(text, strlen(text), 2048, esc, sizeof esc);
    size_t o = 0;
    for (const char *s = esc; *s && o + 8 < len;) {
        size_t n;
        const char *spelt;
        if ((unsigned char)*s < 0x80) {
            out[o++] = *s++;
        } else if (strncmp(s, "◆ f", strlen("◆ f")) == 0) {
            /* "Frequency 0.712 Hz ◆ f1": the drive is on natural frequency 1 */
            o += (size_t)snprintf(out + o, len - o, "= f");
            s += strlen("◆ f");
        } else if ((spelt = spell_ascii(s, &n)) != NULL) {
            o += (size_t)snprintf(out + o, len - o, "%s", spelt);
            s += n;
        } else if (utf8) {
            do
                out[o++] = *s++;
            while (((unsigned char)*s & 0xc0) == 0x80 && o + 1 < len);
        } else {
            o += (size_t)snprintf(out + o, len - o, "\\x%02x", (unsigned char)*s++);
        }
    }
    out[o < len ? o : len - 1] = '\0';
}

