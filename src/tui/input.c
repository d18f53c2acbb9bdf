/* input.c: the key table (nnn's bindings[] idea): keys to actions in one place. */
#include "input.h"

#include <string.h>

#include <curses.h>

#define CTRL(c) ((c) & 0x1f)

const struct binding input_bindings[] = {
    {' ', ACT_RUN, "space", "space", "start / pause", false},
    {'.', ACT_STEP, ".", ".", "step forward one dt (pauses)", false},
    {',', ACT_BACK, ",", ",", "step back one dt (paused; up to 500 states)", false},
    {'r', ACT_RESET, "r", "r", "reset to the initial conditions, t = 0", false},
    {'R', ACT_RANDOM, "R", "R", "random initial positions", false},
    {'p', ACT_PRESETS, "p", "p", "preset menu", false},
    {'L', ACT_LESSONS, "L", "L", "lesson menu (lesson: space on, , back, Esc leaves)", false},
    {'1', ACT_ENLARGE, "1-6", "1-6",
     "enlarge: 1 x, 2 v, 3 a, 4 x-v, 5 x-a, 6 v-a (again: grid)", false},
    {'2', ACT_ENLARGE, "1-6", "1-6", NULL, false},
    {'3', ACT_ENLARGE, "1-6", "1-6", NULL, false},
    {'4', ACT_ENLARGE, "1-6", "1-6", NULL, false},
    {'5', ACT_ENLARGE, "1-6", "1-6", NULL, false},
    {'6', ACT_ENLARGE, "1-6", "1-6", NULL, false},
    {'0', ACT_GRID, "0", "0", "all plots again (the grid)", false},
    {'<', ACT_NARROWER, "<", "<", "shorter time window: 60, 30, 20, 10, 5, 2, 1 s", false},
    {'>', ACT_WIDER, ">", ">", "longer time window (default 10 s)", false},
    {'m', ACT_MODES, "m", "m", "modes view: live shapes, damping, energy (again: plots)", false},
    {'f', ACT_RESPONSE, "f", "f", "frequency response view: amplitude and phase (again: plots)", false},
    {'e', ACT_ENERGY, "e", "e", "energy view: the balance and its drift (again: plots)", false},
    {'F', ACT_SPECTRUM, "F", "F", "spectrum view of the selected mass (again: plots)", false},
    {'g', ACT_GHOST, "g", "g", "ghost: a frozen copy run beside the chain (again: drop it)", false},
    {'v', ACT_HIDE, "v", "v", "show / hide the selected mass's curves (Tab, ↑↓ to a mass)", false},
    {'n', ACT_NEAREST, "n", "n", "drive at the nearest natural frequency", false},
    {'w', ACT_SWEEP, "w", "w", "start / stop a sine sweep (f; cubic springs: up, then down)", false},
    {'s', ACT_SAVE, "s", "s", "save the set-up as a preset", false},
    {'x', ACT_EXPORT, "x", "x", "export the samples as CSV (f view: the sweep's points)", false},
    {'X', ACT_FIGURE, "X", "X", "report figure of the view (asks its name): SVG, PNG", false},
    {'|', ACT_CURSOR, "|", "|", "time cursor, readout; again: a second cursor; again: none", false},
    {KEY_UP, ACT_UP, "↑", "Up", "select the control above (chain: element to the left)", false},
    {'k', ACT_UP, "k", "k", NULL, false},
    {KEY_DOWN, ACT_DOWN, "↓", "Down", "select the control below (chain: element to the right)", false},
    {'j', ACT_DOWN, "j", "j", NULL, false},
    {KEY_LEFT, ACT_LEFT, "←", "Left", "decrease, fine (chain: move the mass left)", false},
    {'h', ACT_LEFT, "h", "h", NULL, false},
    {KEY_RIGHT, ACT_RIGHT, "→", "Right", "increase, fine (chain: move the mass right)", false},
    {'l', ACT_RIGHT, "l", "l", NULL, false},
    {KEY_NPAGE, ACT_LEFT_BIG, "PgDn", "PgDn", "decrease, coarse", false},
    {KEY_SLEFT, ACT_LEFT_BIG, "Shift+←", "Shift+Left", NULL, false},
    {'H', ACT_LEFT_BIG, "H", "H", NULL, false},
    {KEY_PPAGE, ACT_RIGHT_BIG, "PgUp", "PgUp", "increase, coarse", false},
    {KEY_SRIGHT, ACT_RIGHT_BIG, "Shift+→", "Shift+Right", NULL, false},
    {'\n', ACT_ENTER, "Enter", "Enter", "type a value (Masses: apply; chain: m, k; modes: start it)", false},
    {KEY_ENTER, ACT_ENTER, "Enter", "Enter", NULL, false},
    {'\r', ACT_ENTER, "Enter", "Enter", NULL, false},
    {'\t', ACT_FOCUS, "Tab", "Tab", "move between controls, chain elements and (m view) modes", false},
    {'c', ACT_DAMPING, "c", "c", "chain: type the selected mass's damping or spring's damper",
     false},
    {'K', ACT_CUBIC_KEY, "K", "K", "chain: type the selected spring's cubic constant k3",
     false},
    {'[', ACT_SLOWER, "[", "[", "playback slower", false},
    {']', ACT_FASTER, "]", "]", "playback faster", false},
    {27, ACT_ESCAPE, "Esc", "Esc", "close the overlay, cancel typing", false},
    /* While a time cursor is shown on the plots, these keys are the cursor's. */
    {KEY_LEFT, ACT_CURSOR_STEP, "←→", "Left/Right",
     "cursor shown: one sample back, on (paused: scrolls too)", true},
    {KEY_RIGHT, ACT_CURSOR_STEP, "←→", "Left/Right", NULL, true},
    {'h', ACT_CURSOR_STEP, "h", "h", NULL, true},
    {'l', ACT_CURSOR_STEP, "l", "l", NULL, true},
    {KEY_SLEFT, ACT_CURSOR_JUMP, "Shift+←→", "Shift+arrows",
     "cursor shown: a tenth of the window earlier, later", true},
    {KEY_SRIGHT, ACT_CURSOR_JUMP, "Shift+←→", "Shift+arrows", NULL, true},
    {'H', ACT_CURSOR_JUMP, "H", "H", NULL, true},
    {'L', ACT_CURSOR_JUMP, "L", "L", NULL, true},
    {KEY_PPAGE, ACT_CURSOR_PAGE, "PgUp", "PgUp",
     "cursor shown, paused: a window back, on (66 s or more kept)", true},
    {KEY_NPAGE, ACT_CURSOR_PAGE, "PgDn", "PgDn", NULL, true},
    {KEY_UP, ACT_CURSOR_MASS, "↑↓", "Up/Down", "cursor shown: measure the mass before, after", true},
    {KEY_DOWN, ACT_CURSOR_MASS, "↑↓", "Up/Down", NULL, true},
    {'k', ACT_CURSOR_MASS, "k", "k", NULL, true},
    {'j', ACT_CURSOR_MASS, "j", "j", NULL, true},
    {27, ACT_CURSOR_OFF, "Esc", "Esc", "cursor shown: remove the cursors", true},
    {CTRL('l'), ACT_REDRAW, "Ctrl+L", "Ctrl+L", "redraw the screen", false},
    {'?', ACT_HELP, "?", "?", "this help (? or Esc closes it)", false},
    {'q', ACT_QUIT, "q", "q", "quit", false},
    {0, ACT_NONE, NULL, NULL, NULL, false},
};

const char *input_key_name(int a, bool utf8)
{
    for (const struct binding *b = input_bindings; b->key; b++)
        if ((int)b->action == a && !b->cursor)
            return utf8 ? b->name : b->ascii;
    return NULL;
}

enum action input_action(int key, bool cursor)
{
    for (int pass = cursor ? 0 : 1; pass < 2; pass++)
        for (const struct binding *b = input_bindings; b->name; b++)
            if (b->key == key && b->cursor == (pass == 0))
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
