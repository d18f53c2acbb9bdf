/* hash.h: FNV-1a, the 64-bit hash the program uses to tell whether something it drew or
 * solved has changed. */
#ifndef SPRINGSIM_HASH_H
#define SPRINGSIM_HASH_H

#include <stddef.h>
#include <stdint.h>

#define HASH_START 0xcbf29ce484222325ULL /* FNV-1a's offset basis */

/* h carried on over the len bytes at p (start from HASH_START). */
uint64_t hash_bytes(uint64_t h, const void *p, size_t len);

#endif
