/* overlay.c: the help, the preset menu, typing and the confirmation: each one's drawing
 * and keys together. */
#include "overlay.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../lab/caption.h"
#include "../app/verb.h"
#include "draw.h"
#include "input.h"
#include "term.h"

#define HELP_WIDTH 80 /* the help box, at most */

#define HELP_MAX_ROWS 160 /* wrapped help rows, at most */

/* The notes after the keys, on the mouse and typing. */
static const char *const notes[] = {
    "",
    "Mouse: click a control to select it, wheel to adjust it; drag a mass (paused) to set "
    "its initial position.",
    "Values can be typed: select a control and press Enter.",
};

/* One row of the help as shown: a binding's keys (or none) and a piece of text. */
struct help_row {
    const struct binding *b; /* the binding whose keys start this row, or NULL */
    const char *text;        /* the text, len bytes of it */
    int len;
    bool note;               /* a note: across the whole box, not in the text column */
};

/* The keys of binding b and the other keys of its action, as the help shows them. */
static void binding_keys(const struct binding *b, char *keys, size_t len)
{
    bool utf8 = term_utf8();
    const char *name = utf8 ? b->name : b->ascii;
    snprintf(keys, len, "%s", name);
    for (const struct binding *o = b + 1; o->name && !o->help; o++) {
        const char *other = utf8 ? o->name : o->ascii;
        if (o->action == b->action && strcmp(other, name) != 0 && !strstr(keys, other))
            snprintf(keys + strlen(keys), len - strlen(keys), " %s", other);
    }
}

/* The help's column of keys: as wide as the widest binding's keys as drawn (14 columns,
 * 17 spelled in ASCII: "PgDn Shift+Left H"). */
static int key_cols(void)
{
    int cols = 0;
    char keys[64];
    for (const struct binding *b = input_bindings; b->name; b++) {
        if (!b->help)
            continue;
        binding_keys(b, keys, sizeof keys);
        int w = draw_width(keys);
        cols = w > cols ? w : cols;
    }
    return cols;
}

/* The help laid out for a box w columns wide: each binding's text, then the notes,
 * wrapped at spaces so no line is cut. Returns the rows. */
static int help_rows_for(int w, struct help_row *rows)
{
    int n = 0;
    const int nnotes = (int)(sizeof notes / sizeof *notes);
    const struct binding *b = input_bindings;
    const int key_w = key_cols();
    for (int note = -1; note < nnotes && n < HELP_MAX_ROWS;) {
        const struct binding *key = NULL;
        const char *text;
        int width;
        if (note < 0) {
            while (b->name && !b->help)
                b++;
            if (!b->name) {
                note = 0;
                continue;
            }
            key = b, text = b->help, width = w - key_w - 5;
            b++;
        } else {
            text = notes[note++], width = w - 4;
        }
        if (width < 8)
            width = 8;
        /* Wrap text at spaces into rows of at most width columns. */
        do {
            const char *end = text, *cut = NULL;
            int cols = 0;
            while (*end && cols < width) {
                if (*end == ' ')
                    cut = end;
                end++;
                while ((*end & 0xC0) == 0x80)
                    end++;
                cols++;
            }
            if (*end && *end != ' ' && cut)
                end = cut;
            rows[n++] = (struct help_row){key, text, (int)(end - text), note >= 0};
            key = NULL;
            text = *end == ' ' ? end + 1 : end;
        } while (*text && n < HELP_MAX_ROWS);
    }
    return n;
}

/* Draws help row h at row y of box r. */
static void help_line(const struct help_row *h, int y, struct rect r)
{
    char text[256];
    snprintf(text, sizeof text, "%.*s", h->len, h->text);
    int key_w = key_cols();
    if (h->b) {
        char keys[64];
        binding_keys(h->b, keys, sizeof keys);
        draw_text_attr(y, r.x + 2, key_w, A_BOLD, keys);
    }
    if (h->note)
        draw_text(y, r.x + 2, r.w - 4, text);
    else
        draw_text(y, r.x + 3 + key_w, r.w - key_w - 5, text);
}

/* A centred box of h x w, cleared, with a title. */
static struct rect overlay_box(const struct layout *l, int h, int w, const char *title)
{
    if (h > l->rows - 2)
        h = l->rows - 2;
    if (w > l->cols - 2)
        w = l->cols - 2;
    struct rect r = {(l->rows - h) / 2, (l->cols - w) / 2, h, w};
    /* A blank cell around it, so no frame or highlight beneath shows at its edge; the
     * status line and the hints stay. */
    int x0 = r.x > 0 ? r.x - 1 : 0, y0 = r.y > 1 ? r.y - 1 : r.y;
    int x1 = r.x + r.w < l->cols ? r.x + r.w + 1 : l->cols;
    int y1 = r.y + r.h < l->rows - 1 ? r.y + r.h + 1 : r.y + r.h;
    draw_clear((struct rect){y0, x0, y1 - y0, x1 - x0});
    draw_frame(r, title, true);
    return r;
}

/* The help box's width on this screen. */
static int help_width(const struct layout *l)
{
    return HELP_WIDTH < l->cols - 2 ? HELP_WIDTH : l->cols - 2;
}

/* Rows of help text the box shows at a time, for n rows of help. */
static int help_visible(const struct layout *l, int n)
{
    int h = n + 3;
    if (h > l->rows - 2)
        h = l->rows - 2;
    return h - 3;
}

static void draw_help(const struct overlay *o, const struct layout *l)
{
    struct help_row help[HELP_MAX_ROWS];
    int n = help_rows_for(help_width(l), help);
    struct rect r = overlay_box(l, n + 3, HELP_WIDTH, "Keys");
    int rows = r.h - 3, top = o->help_top;
    if (top > n - rows) /* the screen grew since the last scroll */
        top = n - rows > 0 ? n - rows : 0;
    for (int i = 0; i < rows && top + i < n; i++)
        help_line(&help[top + i], r.y + 1 + i, r);
    /* Where the view is, so the end is never a guess. */
    char foot[120];
    if (rows >= n)
        snprintf(foot, sizeof foot, "all %d lines; ? or Esc closes", n);
    else {
        /* The longest form that fits: where the view is comes first. */
        const char *more = top + rows >= n ? " (end)" : " ▼ more";
        snprintf(foot, sizeof foot, "lines %d–%d of %d%s  ↑↓ PgUp PgDn scroll  Esc closes",
                 top + 1, top + rows, n, more);
        if (draw_width(foot) > r.w - 4)
            snprintf(foot, sizeof foot, "lines %d–%d of %d%s  ↑↓ PgUp PgDn", top + 1,
                     top + rows, n, more);
    }
    draw_text_attr(r.y + r.h - 2, r.x + 2, r.w - 4, term_attr(PAIR_TITLE), foot);
}

/* A menu's rows in box r, scrolled to keep the selected row shown: each the name
 * padded to name_w and its text (row(o, i, &name, &text)); the keys it takes below. */
static void draw_menu(const struct overlay *o, struct rect r, int n, int sel, int name_w,
                      void (*row)(const struct overlay *o, int i, const char **name,
                                  const char **text),
                      const char *keys)
{
    int rows = r.h - 4, first = sel >= rows ? sel - rows + 1 : 0;
    for (int i = first; i < n && i - first < rows; i++) {
        const char *name, *text;
        row(o, i, &name, &text);
        if (i == sel)
            attron(term_attr(PAIR_SELECT));
        mvhline(r.y + 1 + i - first, r.x + 1, ' ', r.w - 2);
        int pad = name_w - draw_width(name); /* in screen columns: CJK takes two */
        draw_printf(r.y + 1 + i - first, r.x + 2, r.w - 4, "%s%*s %s", name, pad > 0 ? pad : 0,
                    "", text);
        if (i == sel)
            attroff(term_attr(PAIR_SELECT));
    }
    draw_text_attr(r.y + r.h - 2, r.x + 2, r.w - 4, term_attr(PAIR_TITLE), keys);
}

static void preset_row(const struct overlay *o, int i, const char **name, const char **text)
{
    *name = o->presets[i].name;
    *text = o->presets[i].about;
}

/* A lesson's name and title as shown: escaped (a U+202E in a file would turn the line
 * around), spelled in ASCII without UTF-8. */
static void lesson_row(const struct overlay *o, int i, const char **name, const char **text)
{
    static char safe_name[4 * 256 + 8], safe_title[4 * 200 + 8];
    caption_text(o->lessons[i].name, term_utf8(), safe_name, sizeof safe_name);
    caption_text(o->lessons[i].about, term_utf8(), safe_title, sizeof safe_title);
    *name = safe_name;
    *text = safe_title;
}

static void draw_presets(const struct overlay *o, const struct layout *l)
{
    int n = o->npresets, longest = 0;
    /* As wide as the longest description needs, where the screen has room. */
    for (int i = 0; i < n; i++) {
        int d = draw_width(o->presets[i].about);
        longest = d > longest ? d : longest;
    }
    int w = 2 + 15 + 1 + longest + 2;
    struct rect r = overlay_box(l, (n ? n : 1) + 4, w > 76 ? w : 76, "Presets");
    if (n == 0)
        draw_text(r.y + 1, r.x + 2, r.w - 4, "No presets found on the search path.");
    else
        draw_menu(o, r, n, o->preset_sel, 15, preset_row, "↑↓ choose   Enter load   Esc close");
}

static void draw_lessons(const struct overlay *o, const struct layout *l)
{
    int n = o->nlessons, name_w = 10;
    /* The names' column as wide as the longest name (transmissibility: 16). */
    for (int i = 0; i < n; i++) {
        int d = draw_width(o->lessons[i].name);
        name_w = d > name_w && d <= 24 ? d : name_w;
    }
    struct rect r = overlay_box(l, (n ? n : 1) + 4, 96, "Lessons");
    if (n == 0)
        draw_text(r.y + 1, r.x + 2, r.w - 4, "No lessons found on the search path.");
    else
        draw_menu(o, r, n, o->lesson_sel, name_w, lesson_row,
                  "↑↓ choose   Enter start   Esc close");
}

/* What the prompt says for the text being typed. */
static void edit_prompt(const struct overlay *o, const struct app *app,
                        const struct selection *sel, char *buf, size_t len)
{
    int i = sel->elem / 2;
    switch (o->target) {
    case EDIT_CONTROL:
        snprintf(buf, len, "%s =", app_control_label((enum control)sel->control));
        break;
    case EDIT_MASS:
        snprintf(buf, len, "mass %d: m (kg) =", i + 1);
        break;
    case EDIT_DAMPING:
        snprintf(buf, len, "mass %d: c (N·s/m) =", i + 1);
        break;
    case EDIT_SPRING: {
        char name[48];
        app_spring_name(app->model, i, name, sizeof name);
        snprintf(buf, len, "%s: k (N/m) =", name);
        break;
    }
    case EDIT_CUBIC:
    case EDIT_SPRING_DAMPER: {
        char name[48];
        app_spring_name(app->model, i, name, sizeof name);
        snprintf(buf, len, o->target == EDIT_CUBIC ? "%s: k3 (N/m³) =" : "%s: c (N·s/m) =",
                 name);
        break;
    }
    case EDIT_SAVE:
        snprintf(buf, len, "save preset as:");
        break;
    case EDIT_FIGURE:
        snprintf(buf, len, "figure name [%.40s]:", o->save_name);
        break;
    }
}

void overlay_draw(const struct overlay *o, const struct app *app, const struct layout *l,
                  const struct selection *sel)
{
    int y = l->hints.y;
    switch (o->kind) {
    case OVERLAY_HELP:
        draw_help(o, l);
        break;
    case OVERLAY_PRESETS:
        draw_presets(o, l);
        break;
    case OVERLAY_LESSONS:
        draw_lessons(o, l);
        break;
    case OVERLAY_EDIT: {
        char prompt[80];
        edit_prompt(o, app, sel, prompt, sizeof prompt);
        mvhline(y, 0, ' ', l->cols);
        attron(A_BOLD);
        int x = 1 + draw_printf(y, 1, l->cols - 1, "%s %s", prompt, o->edit);
        attroff(A_BOLD);
        const char *how = o->target == EDIT_FIGURE ? "_   (Enter saves, Esc cancels)"
                                                   : "_   (Enter sets it, Esc cancels)";
        draw_text(y, x, l->cols - x, how);
        break;
    }
    case OVERLAY_CONFIRM:
        mvhline(y, 0, ' ', l->cols);
        attron(term_attr(PAIR_WARN));
        draw_printf(y, 1, l->cols - 1, "preset %s exists: replace it? (y/n)", o->save_name);
        attroff(term_attr(PAIR_WARN));
        break;
    case OVERLAY_NONE:
        break;
    }
}

void overlay_help(struct overlay *o)
{
    o->kind = OVERLAY_HELP;
    o->help_top = 0;
}

void overlay_presets(struct overlay *o, const struct app *app)
{
    free(o->presets);
    o->npresets = preset_scan(app->exe_dir, &o->presets);
    o->preset_sel = 0;
    for (int i = 0; i < o->npresets; i++)
        if (strcmp(o->presets[i].name, app->preset) == 0)
            o->preset_sel = i;
    o->kind = OVERLAY_PRESETS;
}

void overlay_lessons(struct overlay *o, const struct app *app)
{
    free(o->lessons);
    o->nlessons = lesson_scan(app->exe_dir, &o->lessons);
    o->lesson_sel = 0;
    o->chosen[0] = '\0';
    o->kind = OVERLAY_LESSONS;
}

void overlay_edit(struct overlay *o, enum edit_target target)
{
    o->kind = OVERLAY_EDIT;
    o->target = target;
    o->edit[0] = '\0';
    o->edit_len = 0;
}

void overlay_figure(struct overlay *o, const char *def)
{
    overlay_edit(o, EDIT_FIGURE);
    snprintf(o->save_name, sizeof o->save_name, "%s", def);
}

void overlay_free(struct overlay *o)
{
    free(o->presets);
    o->presets = NULL;
    o->npresets = 0;
    free(o->lessons);
    o->lessons = NULL;
    o->nlessons = 0;
}

/* One element from the text typed (verb.h): what = 'm', 'c' or 'k'. */
static unsigned set_element(const struct overlay *o, struct app *app, char what, int i)
{
    unsigned changed;
    verb_do(app, ACT_ELEMENT, &(struct verb_arg){.what = what, .index = i, .text = o->edit},
            &changed);
    return changed;
}

/* Acts on the text typed, by what it was for; the app says what came of it. */
static unsigned finish_edit(struct overlay *o, struct app *app, const struct selection *sel)
{
    int i = sel->elem / 2;
    unsigned changed = 0;
    switch (o->target) {
    case EDIT_CONTROL:
        if (o->edit_len)
            verb_do(app, ACT_SET, &(struct verb_arg){.index = sel->control, .text = o->edit},
                    &changed);
        return changed;
    case EDIT_MASS:
        return set_element(o, app, 'm', i);
    case EDIT_DAMPING:
        return set_element(o, app, 'c', i);
    case EDIT_SPRING:
        return set_element(o, app, 'k', i);
    case EDIT_CUBIC:
    case EDIT_SPRING_DAMPER:
        verb_do(app, o->target == EDIT_CUBIC ? ACT_CUBIC : ACT_SPRING_DAMPING,
                &(struct verb_arg){.index = i, .text = o->edit}, &changed);
        return changed;
    case EDIT_SAVE:
        if (app_save(app, o->edit, false) == SAVE_EXISTS) {
            snprintf(o->save_name, sizeof o->save_name, "%s", o->edit);
            o->kind = OVERLAY_CONFIRM;
        }
        return APP_CHANGED_MESSAGE;
    case EDIT_FIGURE:
        snprintf(o->figure, sizeof o->figure, "%s", o->edit_len ? o->edit : o->save_name);
        return 0;
    }
    return 0;
}

static unsigned edit_key(struct overlay *o, struct app *app, const struct selection *sel, int ch)
{
    if (ch == 27) {
        o->kind = OVERLAY_NONE;
    } else if (ch == '\n' || ch == '\r' || ch == KEY_ENTER) {
        o->kind = OVERLAY_NONE;
        return finish_edit(o, app, sel);
    } else if (ch == KEY_BACKSPACE || ch == 127 || ch == 8) {
        /* A whole character: its UTF-8 continuation bytes too. */
        while (o->edit_len && (o->edit[o->edit_len - 1] & 0xC0) == 0x80)
            o->edit[--o->edit_len] = '\0';
        if (o->edit_len)
            o->edit[--o->edit_len] = '\0';
    } else if (((ch >= 32 && ch < 127) || (ch >= 128 && ch < 256)) &&
               o->edit_len < (int)sizeof o->edit - 1) {
        o->edit[o->edit_len++] = (char)ch;
        o->edit[o->edit_len] = '\0';
    }
    return 0;
}

/* A menu's keys: up and down move the choice *sel among n, Enter picks it, Esc, q and
 * the key that opened the menu close it. True when Enter picked a choice (the menu is
 * closed then too). */
static bool menu_key(struct overlay *o, int *sel, int n, enum action a, enum action opener)
{
    if (a == ACT_UP || a == ACT_DOWN) {
        *sel += a == ACT_UP ? -1 : 1;
        *sel = *sel > n - 1 ? n - 1 : *sel;
        *sel = *sel < 0 ? 0 : *sel;
        return false;
    }
    if (a == ACT_ENTER || a == ACT_ESCAPE || a == ACT_QUIT || a == opener)
        o->kind = OVERLAY_NONE;
    return a == ACT_ENTER && n > 0;
}

static unsigned preset_key(struct overlay *o, struct app *app, enum action a)
{
    unsigned changed = 0;
    if (menu_key(o, &o->preset_sel, o->npresets, a, ACT_PRESETS)) {
        const struct search_entry *e = &o->presets[o->preset_sel];
        verb_do(app, ACT_PRESET, &(struct verb_arg){.text = e->path, .name = e->name},
                &changed);
    }
    return changed;
}

static void lesson_key(struct overlay *o, enum action a)
{
    if (menu_key(o, &o->lesson_sel, o->nlessons, a, ACT_LESSONS))
        snprintf(o->chosen, sizeof o->chosen, "%s", o->lessons[o->lesson_sel].path);
}

/* Scrolls the help; the screen's size bounds it when drawn. */
static void help_key(struct overlay *o, const struct layout *l, int ch)
{
    struct help_row help[HELP_MAX_ROWS];
    int n = help_rows_for(help_width(l), help), rows = help_visible(l, n);
    int page = rows > 1 ? rows - 1 : 1, last = n - rows;
    switch (ch) {
    case KEY_UP:
    case 'k':
        o->help_top--;
        break;
    case KEY_DOWN:
    case 'j':
        o->help_top++;
        break;
    case KEY_PPAGE:
        o->help_top -= page;
        break;
    case KEY_NPAGE:
    case ' ':
        o->help_top += page;
        break;
    case KEY_HOME:
        o->help_top = 0;
        break;
    case KEY_END:
        o->help_top = n;
        break;
    default: {
        enum action a = input_action(ch, false);
        if (a == ACT_HELP || a == ACT_ESCAPE || a == ACT_QUIT)
            o->kind = OVERLAY_NONE;
        break;
    }
    }
    if (o->help_top > last)
        o->help_top = last;
    if (o->help_top < 0)
        o->help_top = 0;
}

unsigned overlay_key(struct overlay *o, struct app *app, const struct selection *sel,
                     const struct layout *l, int ch)
{
    switch (o->kind) {
    case OVERLAY_EDIT:
        return edit_key(o, app, sel, ch);
    case OVERLAY_CONFIRM:
        o->kind = OVERLAY_NONE;
        if (ch == 'y' || ch == 'Y')
            return app_save(app, o->save_name, true) == SAVE_OK ? APP_CHANGED_MESSAGE : 0;
        app_say(app, SAID_NOTE, "not saved: %s kept as it was", o->save_name);
        return APP_CHANGED_MESSAGE;
    case OVERLAY_HELP:
        help_key(o, l, ch);
        return 0;
    case OVERLAY_PRESETS:
        return preset_key(o, app, input_action(ch, false));
    case OVERLAY_LESSONS:
        lesson_key(o, input_action(ch, false));
        return 0;
    case OVERLAY_NONE:
        break;
    }
    return 0;
}
