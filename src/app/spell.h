/* spell.h: the program's own non-ASCII characters (arrows, box lines, symbols) spelled in
 * ASCII, for a terminal without UTF-8 and for the plain mode. */
#ifndef SPRINGSIM_SPELL_H
#define SPRINGSIM_SPELL_H

#include <stddef.h>

/* The ASCII spelling of the character starting at s when it is one of ours, its length
 * in bytes into *len; NULL when it is not. A root sign takes its bare operand with it
 * ("√20" is "sqrt(20)", *len covering both; the spelling then lasts to the next call). */
const char *spell_ascii(const char *s, size_t *len);

#endif
