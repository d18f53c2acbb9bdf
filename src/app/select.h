/* select.h: what the keyboard has selected: a control in the panel, an element of the
 * chain (springs and masses, left to right), or a mode in the modes view. Pure, so the
 * rules are tested. */
#ifndef SPRINGSIM_SELECT_H
#define SPRINGSIM_SELECT_H

#include <stdbool.h>

#include "../core/model.h"

enum focus { FOCUS_CONTROLS, FOCUS_CHAIN, FOCUS_MODES };

struct selection {
    enum focus focus; /* where the arrows act */
    int control;      /* selected control (enum control) */
    int elem;         /* selected element: 2j is spring j, 2i+1 is mass i */
    int mode;         /* selected mode in the modes view, 0 the lowest */
    int control_top;  /* the first control shown where they do not all fit */
};

/* Elements the chain has: N+1 springs (N with a free end) and N masses. */
int select_elements(const struct model *m);

/* The selected mass, or -1 when the focus is not on a mass of the chain. */
int select_mass(const struct selection *s);

/* The selected spring, or -1 when the focus is not on a spring of the chain. */
int select_spring(const struct selection *s);

/* The selected mode, or -1 when the focus is not on the modes view. */
int select_mode(const struct selection *s);

/* Keeps the element and the mode selected ones that exist in m (after the chain
 * changed). */
void select_clamp(struct selection *s, const struct model *m);

/* Moves the selection by dir (+1 down / right, -1 up / left), wrapping around. */
void select_move(struct selection *s, int dir, int ncontrols, const struct model *m);

/* The first of ncontrols controls to show in rows rows: the same as last time unless
 * the selected control would be out of sight, then the least scroll that shows it. */
int select_control_top(struct selection *s, int rows, int ncontrols);

/* Moves the focus on: the controls, the chain (landing on mass 1), then the modes when
 * modes_shown, and round again. */
void select_toggle_focus(struct selection *s, const struct model *m, bool modes_shown);

#endif
