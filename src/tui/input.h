/* input.h: the one table that maps keys to actions. The help overlay, `--keys` and
 * the man page's key list all come from it (a test checks the man page). */
#ifndef SPRINGSIM_INPUT_H
#define SPRINGSIM_INPUT_H

#include <stdbool.h>
#include <stdio.h>

#include "../app/command.h"

struct binding {
    int key;          /* curses key code or character */
    enum action action;
    const char *name; /* the key as shown, UTF-8 */
    const char *ascii; /* the key as shown without UTF-8 */
    const char *help; /* what it does; NULL for a second key of the same action */
    bool cursor;      /* only while a time cursor is shown on the plots, and then before
                       * the key's other binding */
};

/* The bindings, ending with {0, ACT_NONE, ...}. */
extern const struct binding input_bindings[];

/* The action of a key, or ACT_NONE; with cursor (a time cursor shown on the plots) the
 * cursor's binding of the key comes first. */
enum action input_action(int key, bool cursor);

/* The key of action a as shown (the first binding's; its ASCII name without utf8), or
 * NULL for an action no key has. */
const char *input_key_name(int a, bool utf8);

/* Prints the key table, one "KEY<TAB>WHAT" line per action (for --keys). */
void input_print_keys(FILE *out);

#endif
