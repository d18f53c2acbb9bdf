/* keys.h: what a key or the mouse does in the terminal program: the actions that are
 * verbs go through their rows of the table of user verbs (app/verb.h) with their
 * argument from the screen (the selection, the view shown); the rest is the screen's own
 * table (overlays, focus, the arrows in the panels, views, lessons' keys). */
#ifndef SPRINGSIM_KEYS_H
#define SPRINGSIM_KEYS_H

#include <stdbool.h>

#include "screen.h"

/* Does what key ch (a curses key code, KEY_MOUSE, KEY_RESIZE) asks, and writes what it
 * did to the recording (--record); false to quit. */
bool keys_on_key(struct tui *t, int ch);

/* After a lesson took a key or started: the view it asked for, and the screen laid out
 * again when its panel came or went. */
void keys_after_teach(struct tui *t, bool was_shown);

#endif
