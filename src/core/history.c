/* history.c: fixed-capacity ring of sim snapshots, allocated once. */
#include "history.h"

#include <stdlib.h>

struct history {
    int capacity; /* slots */
    int size;     /* doubles per snapshot */
    int head;     /* slot the next push writes */
    int count;    /* saved states */
    double *buf;  /* capacity * size doubles */
};

struct history *history_new(const struct sim *s, int capacity)
{
    struct history *h = calloc(1, sizeof *h);
    if (!h)
        return NULL;
    h->capacity = capacity;
    h->size = sim_snapshot_size(s);
    h->buf = malloc((size_t)capacity * (size_t)h->size * sizeof *h->buf);
    if (!h->buf) {
        free(h);
        return NULL;
    }
    return h;
}

void history_free(struct history *h)
{
    if (h)
        free(h->buf);
    free(h);
}

void history_push(struct history *h, const struct sim *s)
{
    sim_save(s, h->buf + (size_t)h->head * (size_t)h->size);
    h->head = (h->head + 1) % h->capacity;
    if (h->count < h->capacity)
        h->count++;
}

int history_pop(struct history *h, struct sim *s)
{
    if (h->count == 0)
        return -1;
    h->head = (h->head + h->capacity - 1) % h->capacity;
    h->count--;
    sim_restore(s, h->buf + (size_t)h->head * (size_t)h->size);
    return 0;
}

int history_count(const struct history *h)
{
    return h->count;
}

void history_clear(struct history *h)
{
    h->count = 0;
    h->head = 0;
}
