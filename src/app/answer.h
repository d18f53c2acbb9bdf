/* answer.h: the terminal's answers to the start-up queries told from keys, whenever they
 * arrive: the bytes read from the terminal (or the keys curses hands over) go through one
 * scanner, which holds what may be an answer, swallows every answer whole and hands on the
 * rest as keys, in the order they were typed. An answer is
 *   CSI ? ... F     (any final byte F: device attributes "c", XTSMGRAPHICS "S", ...)
 *   CSI ... t       (window and cell sizes), CSI ... c (device attributes)
 *   OSC ... ST/BEL  (colours: the background, the palette)
 *   APC ... ST      (kitty's graphics answer "_G...")
 *   DCS ... ST      (DECRQSS, XTGETTCAP)
 * (each also with its 8-bit introducer, 0x9b CSI, 0x9d OSC, 0x9f APC, 0x90 DCS, and a
 * string with 8-bit ST 0x9c, where no UTF-8 character is under way). No key starts like
 * these but Alt with [, ], _ or P. A sequence cut short
 * (by a byte no answer holds: a control character, an Esc, a curses key code; or, after
 * ANSWER_GAP seconds without its next byte, by one that no answer holds there) is given
 * back as keys when it is only Esc and the introducer, and dropped otherwise (a
 * terminal's garbage or an answer cut off: its bytes as keys would act at random). A
 * terminal's bytes come in order with no key between them, so a part held goes on with
 * the rest of its answer however late that comes (a slow link parts answers), within
 * ANSWER_TAIL of its first byte (a terminal's garbage that never ends takes no key typed
 * after that: q quits). A complete
 * CSI sequence that is no answer (a key curses did not know, a focus event, a paste's end
 * alone, a terminal's garbage) is dropped too: as keys its [ and digits would change the
 * speed and the views. A string longer than ANSWER_MAX is
 * swallowed to its end, and so is a CSI that long. A lone Esc is given back once nothing
 * followed it for ANSWER_ESC_WAIT seconds (answer_idle), or ANSWER_ESC_HOLD while answers
 * are awaited; an answer's rest that comes after it went (parted right after its Esc) is
 * still held and swallowed, the Esc alone having acted.
 * Text pasted between CSI 200 ~ and CSI 201 ~ (bracketed paste) is no keys either: it is
 * kept in paste (to its first control byte) for the caller to route or drop; a paste
 * whose end does not come within ANSWER_GAP seconds ends there. */
#ifndef SPRINGSIM_ANSWER_H
#define SPRINGSIM_ANSWER_H

#include <stdbool.h>
#include <stddef.h>

#define ANSWER_MAX 512   /* bytes an answer holds, at most */
#define ANSWER_KEYS 1024 /* keys waiting, at most (older ones are kept, newer dropped) */
#define ANSWER_GAP 1.0   /* seconds a part-answer waits for its next byte */
#define ANSWER_ESC_HOLD 0.3 /* seconds a lone Esc waits for more while answers are due */
#define ANSWER_ESC_WAIT 0.1 /* and otherwise (a link that parts what a terminal sends) */
#define ANSWER_TAIL 5.0     /* seconds after an Esc went as a key that an answer's rest
                             * may still follow it */
#define ANSWER_PASTE 255    /* bytes of a paste's text kept, at most */
#define ANSWER_BURST 16     /* printable keys read at once that are a paste, at least */

struct answer_scan {
    int held[ANSWER_MAX]; /* what may be an answer, so far */
    int nheld;
    double last;         /* when its last byte came (seconds, any clock) */
    double began;        /* when its first came (or the Esc before it: tail) */
    int keys[ANSWER_KEYS]; /* keys given back, oldest first from key_at */
    int nkeys, key_at;
    char answer[ANSWER_MAX + 1]; /* the answer answer_feed last completed, NUL-ended */
    size_t answer_len;
    int answers;         /* answers swallowed so far */
    int dropped;         /* broken answers dropped so far (too long, cut off), and CSI
                          * sequences that are no answer */
    bool skipping;       /* inside a CSI too long to hold: swallowed to its final byte */
    int utf8_left;       /* continuation bytes the last UTF-8 character typed still has
                          * (so a 0x9b inside one is no 8-bit CSI) */
    bool truncated;      /* the string held lost its text (longer than ANSWER_MAX) */
    bool esc_out;        /* the last input was a lone Esc given as a key, */
    double esc_at;       /* at that time */
    bool pasting;        /* inside a bracketed paste: CSI 200 ~ came, CSI 201 ~ not yet */
    int paste_end;       /* bytes of CSI 201 ~ matched so far */
    bool paste_cut;      /* its text stopped at a control byte (a new line) */
    char paste[ANSWER_PASTE + 1]; /* the last paste's text to its first control byte */
    size_t paste_len;
    int pastes;          /* pastes ended (bracketed, or a burst: answer_burst) not taken */
    bool tail;           /* what is held follows that Esc: held[0] stands for it */
};

/* Feeds one input: a byte (0..255), or a curses key code above 255, that came at `now`
 * seconds. True when it completed an answer: in s->answer until the next call. What
 * turns out to be keys waits for answer_key. */
bool answer_feed(struct answer_scan *s, int ch, double now);

/* Nothing more is waiting to be read at `now`: a lone Esc held ANSWER_ESC_WAIT seconds
 * is a key. */
void answer_idle(struct answer_scan *s, double now);

/* The same while answers are awaited: a lone Esc waits ANSWER_ESC_HOLD seconds first, and
 * an introducer held after an Esc that went as a key ANSWER_TAIL (not ANSWER_GAP) for
 * the rest of its answer. */
void answer_idle_awaiting(struct answer_scan *s, double now);

/* Keys read at once that are a paste, not typing (ANSWER_BURST printable ones or more,
 * from a terminal without bracketed paste): dropped, their text kept as a paste's. The
 * keys dropped. */
int answer_burst(struct answer_scan *s);

/* The last paste's text given back as keys (into a value being typed). */
void answer_paste_keys(struct answer_scan *s);

/* The next key, oldest first, or -1 when none waits. */
int answer_key(struct answer_scan *s);

/* True while a part-answer is held. */
bool answer_holding(const struct answer_scan *s);

#endif
