/* input.c: the key table (nnn's bindings[] idea): keys to actions in one place. */
#include "input.h"

#include <string.h>

#include <curses.h>

#define CTRL(c) ((c) & 0x1f)

const struct binding input_bindings[] = {
    {' ', ACT_RUN, "space", "space", "start / pause"},
    {'.', ACT_STEP, ".", ".", "step forward one dt (pauses)"},
    {',', ACT_BACK, ",", ",", "step back one dt (paused; up to 500 states)"},
    {'r', ACT_RESET, "r", "r", "reset to the initial conditions, t = 0"},
    {'R', ACT_RANDOM, "R", "R", "random initial positions"},
    {'p', ACT_PRESETS, "p", "p", "preset menu"},
    {'1', ACT_ENLARGE, "1-6", "1-6",
     "enlarge: 1 x, 2 v, 3 a, 4 x-v, 5 x-a, 6 v-a (again: grid)"},
    {'2', ACT_ENLARGE, "1-6", "1-6", NULL},
    {'3', ACT_ENLARGE, "1-6", "1-6", NULL},
    {'4', ACT_ENLARGE, "1-6", "1-6", NULL},
    {'5', ACT_ENLARGE, "1-6", "1-6", NULL},
    {'6', ACT_ENLARGE, "1-6", "1-6", NULL},
    {'0', ACT_GRID, "0", "0", "all plots again (the grid)"},
    {'<', ACT_NARROWER, "<", "<", "shorter time window: 60, 30, 20, 10, 5, 2, 1 s"},
    {'>', ACT_WIDER, ">", ">", "longer time window (default 10 s)"},
    {'m', ACT_MODES, "m", "m", "modes view: live shapes, damping, energy (again: plots)"},
    {'f', ACT_RESPONSE, "f", "f", "frequency response view: amplitude and phase (again: plots)"},
    {'e', ACT_ENERGY, "e", "e", "energy view: the balance and its drift (again: plots)"},
    {'F', ACT_SPECTRUM, "F", "F", "spectrum view of the selected mass (again: plots)"},
    {'g', ACT_GHOST, "g", "g", "ghost: a frozen copy run beside the chain (again: drop it)"},
    {'n', ACT_NEAREST, "n", "n", "drive at the nearest natural frequency"},
    {'w', ACT_SWEEP, "w", "w", "start / stop a sine-sweep experiment (see it in f)"},
    {'s', ACT_SAVE, "s", "s", "save the set-up as a preset"},
    {'x', ACT_EXPORT, "x", "x", "export the recorded samples as CSV"},
    {KEY_UP, ACT_UP, "↑", "Up", "select the control above (chain: element to the left)"},
    {'k', ACT_UP, "k", "k", NULL},
    {KEY_DOWN, ACT_DOWN, "↓", "Down", "select the control below (chain: element to the right)"},
    {'j', ACT_DOWN, "j", "j", NULL},
    {KEY_LEFT, ACT_LEFT, "←", "Left", "decrease, fine (chain: move the mass left)"},
    {'h', ACT_LEFT, "h", "h", NULL},
    {KEY_RIGHT, ACT_RIGHT, "→", "Right", "increase, fine (chain: move the mass right)"},
    {'l', ACT_RIGHT, "l", "l", NULL},
    {KEY_NPAGE, ACT_LEFT_BIG, "PgDn", "PgDn", "decrease, coarse"},
    {KEY_SLEFT, ACT_LEFT_BIG, "Shift+←", "Shift+Left", NULL},
    {'H', ACT_LEFT_BIG, "H", "H", NULL},
    {KEY_PPAGE, ACT_RIGHT_BIG, "PgUp", "PgUp", "increase, coarse"},
    {KEY_SRIGHT, ACT_RIGHT_BIG, "Shift+→", "Shift+Right", NULL},
    {'L', ACT_RIGHT_BIG, "L", "L", NULL},
    {'\n', ACT_ENTER, "Enter", "Enter", "type a value (Masses: apply; chain: m, k; modes: start it)"},
    {KEY_ENTER, ACT_ENTER, "Enter", "Enter", NULL},
    {'\r', ACT_ENTER, "Enter", "Enter", NULL},
    {'\t', ACT_FOCUS, "Tab", "Tab", "move between controls, chain elements and (m view) modes"},
    {'c', ACT_DAMPING, "c", "c", "chain: type the selected mass's own damping"},
    {'[', ACT_SLOWER, "[", "[", "playback slower"},
    {']', ACT_FASTER, "]", "]", "playback faster"},
    {27, ACT_ESCAPE, "Esc", "Esc", "close the overlay, cancel typing"},
    {CTRL('l'), ACT_REDRAW, "Ctrl+L", "Ctrl+L", "redraw the screen"},
    {'?', ACT_HELP, "?", "?", "this help (? or Esc closes it)"},
    {'q', ACT_QUIT, "q", "q", "quit"},
    {0, ACT_NONE, NULL, NULL, NULL},
};

enum action input_action(int key)
{
    for (const struct binding *b = input_bindings; b->name; b++)
        if (b->key == key)
            return b->action;
    return ACT_NONE;
}

void input_print_keys(FILE *out)
{
    for (const struct binding *b = input_bindings; b->name; b++) {
        if (!b->help)
            continue;
        fprintf(out, "%s", b->name);
        /* The other keys for the same action. */
        for (const struct binding *o = b + 1; o->name && !o->help; o++)
            if (o->action == b->action && strcmp(o->name, b->name) != 0)
                fprintf(out, ", %s", o->name);
        fprintf(out, "\t%s\n", b->help);
    }
}
