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

int select_mode(const struct selection *s)
{
    return s->focus == FOCUS_MODES ? s->mode : -1;
}

void select_clamp(struct selection *s, const struct model *m)
{
    if (s->elem < 0 || s->elem >= select_elements(m))
        s->elem = 1;
    if (s->mode < 0 || s->mode >= m->n)
        s->mode = 0;
}

void select_move(struct selection *s, int dir, int ncontrols, const struct model *m)
{
    if (s->focus == FOCUS_CHAIN) {
        int n = select_elements(m);
        s->elem = ((s->elem + dir) % n + n) % n;
    } else if (s->focus == FOCUS_MODES) {
        s->mode = ((s->mode + dir) % m->n + m->n) % m->n;
    } else {
        s->control = ((s->control + dir) % ncontrols + ncontrols) % ncontrols;
    }
}

void select_toggle_focus(struct selection *s, const struct model *m, bool modes_shown)
{
    if (s->focus == FOCUS_CONTROLS)
        s->focus = FOCUS_CHAIN;
    else if (s->focus == FOCUS_CHAIN && modes_shown)
        s->focus = FOCUS_MODES;
    else
        s->focus = FOCUS_CONTROLS;
    if (s->elem >= select_elements(m) || s->elem % 2 == 0)
        s->elem = 1; /* mass 1 */
    select_clamp(s, m);
}

int select_control_top(struct selection *s, int rows, int ncontrols)
{
    if (rows <= 0 || rows >= ncontrols)
        return s->control_top = 0;
    if (s->control < s->control_top)
        s->control_top = s->control;
    if (s->control >= s->control_top + rows)
        s->control_top = s->control - rows + 1;
    if (s->control_top > ncontrols - rows)
        s->control_top = ncontrols - rows;
    if (s->control_top < 0)
        s->control_top = 0;
    return s->control_top;
}
