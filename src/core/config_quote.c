/* config_quote.c: user text as every message quotes it: control bytes escaped (C's
 * escapes, \xNN for the rest, invalid UTF-8 and C1 controls included), Unicode's format
 * characters and line and paragraph separators as \uXXXX (U+202E would turn the rest of
 * the line around, U+200B hide in it; libunistring knows which they are), other valid
 * UTF-8 kept, long values cut; and numbers as every message and file writes them, with
 * the fewest digits that read back exactly. */
#include "config.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unictype.h>
#include <unistr.h>

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
        ucs4_t uc = 0;
        if (k > 0 && u8_mbtouc(&uc, s + i, k) == (int)k &&
            (uc_is_general_category(uc, UC_CATEGORY_Cf) ||
             uc_is_general_category(uc, UC_CATEGORY_Zl) ||
             uc_is_general_category(uc, UC_CATEGORY_Zp))) {
            char one[16];
            int w = snprintf(one, sizeof one, uc > 0xffff ? "\\U%08x" : "\\u%04x",
                             (unsigned)uc);
            if (used + (size_t)w < len) {
                memcpy(buf + used, one, (size_t)w + 1);
                used += (size_t)w;
            }
            i += k;
        } else if (k > 0) {
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
