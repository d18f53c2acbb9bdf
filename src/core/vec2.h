/* vec2.h: two doubles at a time, through GCC's and Clang's vector extension (SSE2 on
 * x86-64). Each lane takes the same IEEE operation a double alone would, so a loop
 * written with pairs gives the same bits as the loop a value at a time (and no fused
 * multiply-add: -std=c11 contracts nothing, x86-64's baseline has none). */
#ifndef SPRINGSIM_VEC2_H
#define SPRINGSIM_VEC2_H

#include <stdint.h>
#include <string.h>

typedef double vec2 __attribute__((vector_size(16)));        /* two doubles */
typedef uint64_t vec2_bits __attribute__((vector_size(16))); /* two doubles' bits */

/* p[0] and p[1], p aligned or not. */
static inline vec2 vec2_load(const double *p)
{
    vec2 v;
    memcpy(&v, p, sizeof v);
    return v;
}

/* Stores v into p[0] and p[1]. */
static inline void vec2_store(double *p, vec2 v)
{
    memcpy(p, &v, sizeof v);
}

#endif
