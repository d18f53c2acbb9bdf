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
typedef int64_t vec2_mask __attribute__((vector_size(16)));  /* a comparison's lanes: -1 or 0 */

/* p[0] and p[1], p aligned or not. */
static inline vec2 vec2_load(const double *p)
{
    vec2 v;
    memcpy(&v, p, sizeof v);
    return v;
}

/* p[0] and p[1] as two loads, for values just stored one at a time: a processor cannot
 * forward two 8-byte stores still in its store buffer to one 16-byte load, which then
 * waits for them to reach the cache (AMD's and Intel's alike); two loads take each its
 * own store's value at once. An asm keeps the compiler from joining them into one. */
static inline vec2 vec2_load_halves(const double *p)
{
#if defined(__x86_64__) && defined(__SSE2__)
    vec2 v = {p[0], 0.0};
    __asm__("movhpd %1, %0" : "+x"(v) : "m"(p[1]));
    return v;
#else
    return (vec2){p[0], p[1]};
#endif
}

/* Stores v into p[0] and p[1]. */
static inline void vec2_store(double *p, vec2 v)
{
    memcpy(p, &v, sizeof v);
}

/* Each lane of x taken where mask is set, else of y: `mask ? x : y` a lane. */
static inline vec2 vec2_select(vec2_mask mask, vec2 x, vec2 y)
{
    return (vec2)(((vec2_mask)x & mask) | ((vec2_mask)y & ~mask));
}

/* |x| a lane (fabs: the sign bit cleared). */
static inline vec2 vec2_abs(vec2 x)
{
    const vec2_mask magnitude = {INT64_MAX, INT64_MAX};
    return (vec2)((vec2_mask)x & magnitude);
}

/* a > b ? a : b a lane (b where either is a NaN), as MAXPD takes it. */
static inline vec2 vec2_max(vec2 a, vec2 b)
{
#if defined(__x86_64__) && defined(__SSE2__)
    return __builtin_ia32_maxpd(a, b);
#else
    return vec2_select(a > b, a, b);
#endif
}

/* An infinity or a NaN has every exponent bit set, and only then does adding the
 * exponent's lowest bit to its exponent field carry into the sign bit: nonfinite_bit and
 * vec2_nonfinite_bits set the sign bit (bit 63) of what they give for such a value, and
 * for no other. Or-ed over a state, they test it with no branch and no chain of
 * additions a value. */
#define VEC2_EXPONENT UINT64_C(0x7ff0000000000000) /* a double's exponent field */
#define VEC2_EXPONENT_LOW UINT64_C(0x0010000000000000) /* its lowest bit */

static inline uint64_t nonfinite_bit(double x)
{
    uint64_t b;
    memcpy(&b, &x, sizeof b);
    return (b & VEC2_EXPONENT) + VEC2_EXPONENT_LOW;
}

static inline vec2_bits vec2_nonfinite_bits(vec2 x)
{
    const vec2_bits exponent = {VEC2_EXPONENT, VEC2_EXPONENT};
    const vec2_bits low = {VEC2_EXPONENT_LOW, VEC2_EXPONENT_LOW};
    return ((vec2_bits)x & exponent) + low;
}

#endif
