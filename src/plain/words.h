/* words.h: the plain mode's lines made plain: text made safe to print (control bytes and invalid UTF-8 escaped, the
 * program's own symbols in ASCII, other UTF-8 kept only in a UTF-8 locale). */
#ifndef SPRINGSIM_WORDS_H
#define SPRINGSIM_WORDS_H

#include <stdbool.h>
#include <stddef.h>

/* text made safe to print into out (utf8: the locale is UTF-8). */
void plain_text(const char *text, bool utf8, char *out, size_t len);

#endif
