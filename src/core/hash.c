/* hash.c: FNV-1a (hash.h): h = (h xor byte) * 1099511628211 for each byte, from the
 * offset basis 14695981039346656037 (Fowler, Noll and Vo). */
#include "hash.h"

uint64_t hash_bytes(uint64_t h, const void *p, size_t len)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < len; i++)
        h = (h ^ b[i]) * 0x100000001b3ULL;
    return h;
}
