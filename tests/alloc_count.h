/* alloc_count.h: counts the calls of malloc, calloc and realloc (tests/alloc_count.c),
 * for a test linked with -Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc that checks
 * something allocates nothing. A test wrapping more allocators counts them here too. */
#ifndef SPRINGSIM_ALLOC_COUNT_H
#define SPRINGSIM_ALLOC_COUNT_H

extern long allocations; /* allocator calls so far; a test zeroes it or takes differences */

#endif
