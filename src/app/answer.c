/* answer.c: the terminal's answers told from keys (answer.h). */
#include "answer.h"

#include <ctype.h>
#include <string.h>

#define ESC 0x1b

static void push_key(struct answer_scan *s, int ch)
{
    if (s->key_at > 0 && s->key_at == s->nkeys)
        s->key_at = s->nkeys = 0;
    if (s->nkeys == ANSWER_KEYS && s->key_at > 0) {
        memmove(s->keys, s->keys + s->key_at, (size_t)(s->nkeys - s->key_at) * sizeof *s->keys);
        s->nkeys -= s->key_at;
        s->key_at = 0;
    }
    if (s->nkeys < ANSWER_KEYS)
        s->keys[s->nkeys++] = ch;
}

/* What is held was keys after all (but an Esc already given as a key: s->tail). */
static void give_back(struct answer_scan *s)
{
    for (int i = s->tail ? 1 : 0; i < s->nheld; i++)
        push_key(s, s->held[i]);
    s->nheld = 0;
    s->truncated = false;
    s->tail = false;
}

/* What is held stopped short of an answer's end: keys if it is only an Esc and an
 * introducer (Alt with [, ], _ or P), else a broken answer (a terminal's garbage, an
 * answer cut off), dropped: its bytes as keys would act at random. */
static void cut_off(struct answer_scan *s)
{
    if (s->nheld <= 2) {
        give_back(s);
        return;
    }
    s->nheld = 0;
    s->truncated = false;
    s->tail = false;
    s->dropped++;
}

static bool finish(struct answer_scan *s)
{
    for (int i = 0; i < s->nheld; i++)
        s->answer[i] = (char)s->held[i];
    s->answer_len = (size_t)s->nheld;
    s->answer[s->answer_len] = '\0';
    s->nheld = 0;
    s->tail = false;
    if (s->truncated) {
        s->truncated = false;
        s->dropped++;
        return false; /* swallowed, but not read: its text was lost */
    }
    s->answers++;
    return true;
}

/* A whole CSI sequence held (its final byte last): an answer? CSI ? ... anything, and
 * CSI ... t or CSI ... c whatever their parameters (no key ends so; a terminal's
 * garbage such as CSI 4;-5;-7 t is swallowed too). */
static bool csi_answer(const struct answer_scan *s)
{
    int final = s->held[s->nheld - 1];
    return s->held[2] == '?' || final == 't' || final == 'c';
}

/* Whether the CSI held is the start of a bracketed paste, CSI 200 ~. */
static bool paste_start(const struct answer_scan *s)
{
    static const int start[] = {ESC, '[', '2', '0', '0', '~'};
    if (s->nheld != 6)
        return false;
    for (int i = 0; i < 6; i++)
        if (s->held[i] != start[i])
            return false;
    return true;
}

/* ch inside a bracketed paste: its text kept to the first control byte, the paste ended
 * by CSI 201 ~. */
static void paste_byte(struct answer_scan *s, int ch)
{
    static const char end[] = "\033[201~";
    if (ch == end[s->paste_end]) {
        if (++s->paste_end == (int)sizeof end - 1) {
            s->pasting = false;
            s->pastes++;
        }
        return;
    }
    s->paste_end = ch == ESC;
    if (ch < 0x20 || ch == 0x7f || ch > 0xff)
        s->paste_cut = true;
    else if (!s->paste_cut && s->paste_len < ANSWER_PASTE)
        s->paste[s->paste_len++] = (char)ch;
    s->paste[s->paste_len] = '\0';
}

/* ch after ESC [ ...: 0 held, 1 an answer completed, -1 not an answer (ch not taken). */
static int csi_byte(struct answer_scan *s, int ch)
{
    if (ch >= 0x20 && ch <= 0x3f) {
        s->held[s->nheld++] = ch;
        return 0;
    }
    if (ch >= 0x40 && ch <= 0x7e) {
        s->held[s->nheld++] = ch;
        if (csi_answer(s))
            return finish(s);
        if (paste_start(s)) { /* the text that follows is pasted, not typed */
            s->pasting = true;
            s->paste_end = 0;
            s->paste_cut = false;
            s->paste_len = 0;
            s->paste[0] = '\0';
        }
        s->nheld = 0; /* no answer, and no key curses knew: nothing to act on */
        s->dropped++;
        return 0;
    }
    return -1;
}

/* ch inside OSC, APC or DCS: ends at BEL or ST (ESC \, or 0x9c after a byte that is no
 * part of a UTF-8 character: a continuation byte follows one that is); an ESC followed by
 * anything else ends what came before it as keys and begins again. */
static int string_byte(struct answer_scan *s, int ch)
{
    bool after_esc = s->held[s->nheld - 1] == ESC;
    if (ch == 0x9c && !after_esc && s->held[s->nheld - 1] < 0x80) {
        s->held[s->nheld++] = ESC; /* held as ESC \, as 0x9b is as ESC [ */
        s->held[s->nheld++] = '\\';
        return finish(s);
    }
    if (after_esc) {
        if (ch == '\\') {
            s->held[s->nheld++] = ch;
            return finish(s);
        }
        s->nheld--;
        cut_off(s);
        s->held[s->nheld++] = ESC;
        s->began = s->last; /* now: answer_feed set it */
        return -1;
    }
    if (ch == 0x07) {
        s->held[s->nheld++] = ch;
        return finish(s);
    }
    if (ch == ESC || (ch >= 0x20 && ch <= 0xff && ch != 0x7f)) {
        s->held[s->nheld++] = ch;
        return 0;
    }
    return -1;
}

/* Whether the text of a string answer with introducer intro holds ch: the colours' (hex
 * digits, "rgb:", '/'), kitty's ("Gi=31;OK", an error's upper-case name), DCS's hex. */
static bool string_holds(int intro, int ch)
{
    const char *text = intro == ']' ? "/:;?#,.rgb" : intro == '_' ? "=,;:i" : "$+=;|rm";
    return (ch < 0x80 && isxdigit(ch)) || (ch > 0x20 && ch < 0x7f && strchr(text, ch)) ||
           (intro == '_' && ch >= 'A' && ch <= 'Z');
}

/* Whether ch goes on with what is held after ANSWER_GAP seconds without a byte (late) or
 * after an Esc that went as a key. A terminal's bytes come in order with no key between
 * them, so the rest of an answer a slow link parted is what comes next; but only what an
 * answer holds there goes on with it (Alt+[ then a letter typed later is keys): a CSI
 * answer's digits, ';', '?' first and its final c, t or S; a string answer's text (OSC
 * and DCS begin with a digit, DCS perhaps with '>', kitty's APC with G). And nothing goes on with an answer begun ANSWER_TAIL before a late byte: a
 * terminal's cut-off garbage would take every key typed after it (q too) for ever. */
static bool goes_on(const struct answer_scan *s, int ch, bool late, double now)
{
    int intro = s->held[1];
    bool digit = ch >= '0' && ch <= '9';
    if (late && now - s->began > ANSWER_TAIL)
        return false;
    if (intro == '[')
        return digit || ch == ';' || (s->nheld == 2 ? ch == '?' : ch == 'c' || ch == 't' ||
                                                              ch == 'S');
    if (s->nheld > 2 && s->held[s->nheld - 1] == ESC)
        return ch == '\\'; /* ST's second byte */
    if (s->nheld > 2 && !late) /* the rest of an answer after an Esc that went */
        return ch == ESC || ch == 0x07 || (ch > 0x20 && ch < 0x7f);
    if (s->nheld > 2)
        return ch == ESC || ch == 0x07 || string_holds(intro, ch);
    return intro == '_' ? ch == 'G' : digit || (intro == 'P' && ch == '>');
}

/* The 7-bit introducer of an 8-bit one (CSI, OSC, APC, DCS), else 0. */
static int introducer(int ch)
{
    return ch == 0x9b ? '[' : ch == 0x9d ? ']' : ch == 0x9f ? '_' : ch == 0x90 ? 'P' : 0;
}

bool answer_feed(struct answer_scan *s, int ch, double now)
{
    bool late = now - s->last > ANSWER_GAP;
    if (s->pasting && late) { /* its end never came: what comes now is typed */
        s->pasting = false;
        s->pastes++;
    }
    if (s->pasting) {
        s->last = now;
        paste_byte(s, ch);
        return false;
    }
    if (s->nheld > 1 && (late || s->tail) && !goes_on(s, ch, late, now))
        cut_off(s);
    /* The byte after an Esc that went as a key (answer_idle): an answer's introducer
     * begins its rest, held as if the Esc were there (nothing of it is a key). */
    if (s->nheld == 0 && s->esc_out && now - s->esc_at <= ANSWER_TAIL &&
        (ch == '[' || ch == ']' || ch == '_' || ch == 'P')) {
        s->held[s->nheld++] = ESC;
        s->tail = true;
        s->began = s->esc_at;
    }
    s->esc_out = false;
    s->last = now;
    if (s->skipping) {
        if (ch >= 0x20 && ch <= 0x3f)
            return false;
        s->skipping = false;
        if (ch >= 0x40 && ch <= 0x7e)
            return false; /* its final byte */
    }
    for (;;) {
        if (s->nheld == 0) {
            if (introducer(ch) && s->utf8_left == 0) { /* 8-bit: held as ESC [ and so on */
                s->held[s->nheld++] = ESC;
                s->held[s->nheld++] = introducer(ch);
                s->began = now;
                return false;
            }
            if (ch == ESC)
                s->held[s->nheld++] = ch, s->began = now;
            else
                push_key(s, ch);
            s->utf8_left = ch >= 0xc2 && ch <= 0xdf   ? 1
                           : ch >= 0xe0 && ch <= 0xef ? 2
                           : ch >= 0xf0 && ch <= 0xf4 ? 3
                           : ch >= 0x80 && ch <= 0xbf && s->utf8_left > 0 ? s->utf8_left - 1
                                                                         : 0;
            return false;
        }
        if (s->nheld >= ANSWER_MAX - 1) {
            /* Too long to keep: a string goes on to its end, its text dropped; a CSI
             * this long is no answer. */
            if (s->held[1] == '[') {
                s->nheld = 0;
                s->dropped++;
                s->skipping = true;
                return answer_feed(s, ch, now);
            }
            s->nheld = 2;
            s->truncated = true;
        }
        int r;
        if (s->nheld == 1) {
            if (ch == '[' || ch == ']' || ch == '_' || ch == 'P') {
                s->held[s->nheld++] = ch;
                return false;
            }
            give_back(s);
            continue;
        }
        r = s->held[1] == '[' ? csi_byte(s, ch) : string_byte(s, ch);
        if (r >= 0)
            return r == 1;
        if (s->nheld > 1)
            cut_off(s); /* else string_byte began again at its ESC: ch follows it */
    }
}

/* A string held quiet for ANSWER_GAP whose text took bytes no answer holds (a terminal's
 * garbage that never ended, keys typed after it): dropped to the first of them, which and
 * what follows it are given back as the keys they were (q quits). */
static void string_quiet(struct answer_scan *s)
{
    int k = 2;
    while (k < s->nheld && (string_holds(s->held[1], s->held[k]) ||
                            (k == s->nheld - 1 && s->held[k] == ESC))) /* ST's first byte */
        k++;
    if (k == s->nheld || s->truncated)
        return;
    int n = s->nheld - k;
    memmove(s->held, s->held + k, (size_t)n * sizeof *s->held);
    s->nheld = n;
    s->tail = false;
    s->dropped++;
    give_back(s);
}

/* A lone Esc held `hold` seconds is a key (remembered: an answer's rest may follow it);
 * an introducer alone after it, `tail_hold` seconds (Esc then [ typed); a string that
 * took keys, ANSWER_GAP (string_quiet). A longer part stays held: what comes next says
 * (answer_feed). */
static void idle(struct answer_scan *s, double now, double hold, double tail_hold)
{
    if (s->nheld > 2 && s->held[1] != '[' && now - s->last > ANSWER_GAP)
        string_quiet(s);
    if (s->nheld == 1 && now - s->last >= hold - 1e-9) {
        give_back(s);
        s->esc_out = true;
        s->esc_at = now;
    } else if (s->nheld == 2 && s->tail && now - s->last > tail_hold) {
        give_back(s);
    }
}

void answer_idle(struct answer_scan *s, double now)
{
    if (s->pasting && now - s->last > ANSWER_GAP) {
        s->pasting = false;
        s->pastes++;
    }
    idle(s, now, ANSWER_ESC_WAIT, ANSWER_GAP);
}

void answer_idle_awaiting(struct answer_scan *s, double now)
{
    /* An introducer after an Esc that went waits longer too: a link that parted an
     * answer after its Esc may part it again after its [ (its rest would be keys). */
    idle(s, now, ANSWER_ESC_HOLD, ANSWER_TAIL);
}

int answer_burst(struct answer_scan *s)
{
    int printable = 0, n = s->nkeys - s->key_at;
    for (int i = s->key_at; i < s->nkeys; i++)
        printable += s->keys[i] >= 0x20 && s->keys[i] < 0x7f;
    if (printable < ANSWER_BURST)
        return 0;
    s->paste_len = 0;
    for (int i = s->key_at; i < s->nkeys; i++) {
        int k = s->keys[i];
        if (k < 0x20 || k == 0x7f || k > 0xff)
            break;
        if (s->paste_len < ANSWER_PASTE)
            s->paste[s->paste_len++] = (char)k;
    }
    s->paste[s->paste_len] = '\0';
    s->key_at = s->nkeys = 0;
    s->pastes++;
    return n;
}

void answer_paste_keys(struct answer_scan *s)
{
    for (size_t i = 0; i < s->paste_len; i++)
        push_key(s, (unsigned char)s->paste[i]);
}

int answer_key(struct answer_scan *s)
{
    if (s->key_at >= s->nkeys)
        return -1;
    return s->keys[s->key_at++];
}

bool answer_holding(const struct answer_scan *s)
{
    return s->nheld > 0;
}
