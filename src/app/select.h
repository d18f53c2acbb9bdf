/* select.h: what the keyboard has selected: a control in the panel, or an element of
 * the chain (springs and masses, left to right). Pure, so the rules are tested. */
#ifndef SPRINGSIM_SELECT_H
#define SPRINGSIM_SELECT_H

#include "../core/model.h"

enum focus { FOCUS_CONTROLS, FOCUS_CHAIN };

struct selection {
    enum focus focus; /* where the arrows act */
    int control;      /* selected control (enum control) */
    int elem;         /* selected element: 2j is spring j, 2i+1 is mass i */
};

/* Elements the chain has: N+1 springs (N with a free end) and N masses. */
int select_elements(const struct model *m);

/* The selected mass, or -1 when the focus is not on a mass of the chain. */
int select_mass(const struct selection *s);

/* The selected spring, or -1 when the focus is not on a spring of the chain. */
int select_spring(const struct selection *s);

/* Keeps the element selected one that exists in m (after the chain changed). */
void select_clamp(struct selection *s, const struct model *m);

/* Moves the selection by dir (+1 down / right, -1 up / left), wrapping around. */
void select_move(struct selection *s, int dir, int ncontrols, const struct model *m);

/* Switches the focus between the controls and the chain (landing on mass 1). */
void select_toggle_focus(struct selection *s, const struct model *m);

#endif
