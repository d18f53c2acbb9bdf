/* config_value.c: a setting's value in force, read through its row of the table, for
 * what writes settings back out (a saved preset, --summary's columns): one getter, so a
 * new row is written wherever its row says, with no list of fields kept beside it. */
#include "config.h"

#include <stdio.h>
#include <string.h>

/* The model's own copy of key's value, where it holds one. */
static bool from_model(int key, const struct model *m, struct config_value *out)
{
    switch (key) {
    case CFG_MASSES:
        snprintf(out->text, sizeof out->text, "%d", m->n);
        return true;
    case CFG_MASS:
        *out = (struct config_value){.count = m->n, .v = m->m};
        return true;
    case CFG_SPRING:
        *out = (struct config_value){.count = m->n + 1, .v = m->k};
        return true;
    case CFG_SPRING_CUBIC:
        *out = (struct config_value){.count = m->n + 1, .v = m->k3};
        return true;
    case CFG_DAMPING:
        *out = (struct config_value){.count = m->n, .v = m->c};
        return true;
    case CFG_SPRING_DAMPING:
        *out = (struct config_value){.count = m->n + 1, .v = m->cs};
        return true;
    case CFG_FORCE:
        out->one = m->force;
        break;
    case CFG_FORCE_ON:
        snprintf(out->text, sizeof out->text, "%d", m->force_on + 1);
        return true;
    case CFG_BOUNDARY:
        snprintf(out->text, sizeof out->text, "%s", model_boundary_name(m->boundary));
        return true;
    case CFG_WAVE:
        snprintf(out->text, sizeof out->text, "%s", motor_wave_name(m->motor.wave));
        return true;
    case CFG_AMPLITUDE:
        out->one = m->motor.amplitude;
        break;
    case CFG_FREQUENCY:
        out->one = m->motor.frequency;
        break;
    case CFG_NO_COLLISIONS:
        snprintf(out->text, sizeof out->text, "%s", m->collisions ? "false" : "true");
        return true;
    default:
        return false;
    }
    out->count = 1;
    out->v = &out->one;
    return true;
}

void config_get(int key, const struct config *c, const struct model *m,
                struct config_value *out)
{
    const struct config_option *o = &config_options[key];
    const char *at = (const char *)c + o->offset;
    memset(out, 0, sizeof *out);
    out->str = out->text;
    if (m && from_model(key, m, out))
        return;
    switch (o->kind) {
    case CONFIG_NUMBER:
        memcpy(&out->one, at, sizeof out->one);
        out->count = 1;
        out->v = &out->one;
        return;
    case CONFIG_LIST: {
        const struct config_list *l = (const struct config_list *)(const void *)at;
        /* A list never set stands for its default, one value for all. */
        out->count = l->count ? l->count : 1;
        out->one = o->def;
        out->v = l->count ? l->v : &out->one;
        return;
    }
    case CONFIG_WHOLE:
        if (key == CFG_SEED)
            snprintf(out->text, sizeof out->text, "%llu", (unsigned long long)c->seed);
        else
            snprintf(out->text, sizeof out->text, "%d", *(const int *)(const void *)at);
        return;
    case CONFIG_FLAG:
        snprintf(out->text, sizeof out->text, "%s",
                 *(const bool *)(const void *)at ? "true" : "false");
        return;
    case CONFIG_CHOICE: {
        int i;
        memcpy(&i, at, sizeof i);
        snprintf(out->text, sizeof out->text, "%s", o->choice_name(i));
        return;
    }
    case CONFIG_TEXT:
        if (key == CFG_START_MODE) {
            char amp[32];
            config_format_exact(c->start_amp, amp, sizeof amp);
            snprintf(out->text, sizeof out->text, "%d:%s", c->start_mode, amp);
        } else if (key != CFG_PRESET) {
            const char *s;
            memcpy(&s, at, sizeof s);
            out->str = s ? s : "";
        }
        return;
    case CONFIG_MODE:
        return;
    }
}

bool config_in_force(int key, const struct config *c)
{
    switch (key) {
    case CFG_START_MODE:
        return c->start_mode > 0;
    case CFG_RANDOM:
    case CFG_SEED:
        return c->start_mode == 0 && c->random;
    case CFG_X0:
    case CFG_V0:
        return c->start_mode == 0 && !c->random;
    case CFG_SPRING_CUBIC: /* a linear chain's settings are written as they were before */
        for (int i = 0; i < c->spring_cubic.count; i++)
            if (c->spring_cubic.v[i] != 0.0)
                return true;
        return false;
    default:
        return true;
    }
}
