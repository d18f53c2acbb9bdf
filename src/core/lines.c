/* lines.c: a text read whole cut into lines, each checked for a NUL byte and its length. */
#include "lines.h"

#include <string.h>

struct lines lines_of(const char *text, size_t size)
{
    return (struct lines){text, text + size, 0};
}

enum lines_status lines_next(struct lines *r, size_t max, const char **start, const char **eol)
{
    if (r->s >= r->end)
        return LINES_END;
    const char *nl = memchr(r->s, '\n', (size_t)(r->end - r->s));
    *start = r->s;
    *eol = nl ? nl : r->end;
    r->s = nl ? nl + 1 : r->end;
    r->line++;
    if (memchr(*start, '\0', (size_t)(*eol - *start)))
        return LINES_NUL;
    return (size_t)(*eol - *start) > max ? LINES_LONG : LINES_OK;
}
