/* select.c: the keyboard's selection and its rules. */
#include "select.h"

int select_elements(const struct model *m)
{
    return 2 * m->n + (m->boundary == BOUNDARY_FREE ? 0 : 1);
}

int select_mass(const struct selection *s)
{
    return s->focus == FOCUS_CHAIN && s->elem % 2 == 1 ? s->elem / 2 : -1;
}

int select_spring(const struct selection *s)
{
    return s->focus == FOCUS_CHAIN && s->elem % 2 == 0 ? s->elem / 2 : -1;
}

void select_clamp(struct selection *s, const struct model *m)
{
    if (s->elem < 0 || s->elem >= select_elements(m))
        s->elem = 1;
}

void select_move(struct selection *s, int dir, int ncontrols, const struct model *m)
{
    if (s->focus == FOCUS_CHAIN) {
        int n = select_elements(m);
        s->elem = ((s->elem + dir) % n + n) % n;
    } else {
        s->control = ((s->control + dir) % ncontrols + ncontrols) % ncontrols;
    }
}

void select_toggle_focus(struct selection *s, const struct model *m)
{
    s->focus = s->focus == FOCUS_CHAIN ? FOCUS_CONTROLS : FOCUS_CHAIN;
    if (s->elem >= select_elements(m) || s->elem % 2 == 0)
        s->elem = 1; /* mass 1 */
}
