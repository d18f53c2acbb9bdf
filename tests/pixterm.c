/* pixterm.c: a terminal of our own for the pixel tests. Runs a program in a
 * pseudo-terminal of COLS x ROWS cells, answers its queries as a terminal of the kind
 * given would, types keys, and keeps every byte the program wrote in OUT.
 *   sixel  primary device attributes with 4 (sixel), its cell size (CSI 16 t), its
 *          background (OSC 11); "sixel/N" also says it has N colour registers
 *          (XTSMGRAPHICS), which plain "sixel" leaves unanswered as many terminals do
 *   kitty  kitty's graphics query answered OK, device attributes without 4, cell size
 *   vt220  device attributes without 4, cell size: a terminal without images
 *   none   answers nothing
 * KIND may end in "+MS": the answers come MS milliseconds after the queries, as over a
 * slow link. The palette (OSC 4) and the foreground (OSC 10) are answered as xterm's
 * defaults (black on the background given), but for the entries PIXTERM_PALETTE gives
 * ("N=RRGGBB,...,fg=RRGGBB"); PIXTERM_PALETTE=none answers neither. PIXTERM_TERM is the
 * program's TERM (default xterm-256color). PIXTERM_DRIP=MS sends the answers a byte every
 * MS milliseconds; PIXTERM_PART=MS parts them 4 bytes into the last one (device
 * attributes), its rest MS milliseconds later, as a slow link may.
 * KEYS is typed one character every 0.3 s; '~' waits a second instead; "\e" is
 * Esc; a first character '^' types the one after it as soon as the queries are seen,
 * before any answer. The
 * program gets TERM=xterm-256color, no TMUX or STY. Exits when it does, or after 30 s;
 * with PIXTERM_RSS=FILE, the program's peak resident memory in kB is written to FILE.
 * usage: pixterm KIND COLS ROWS CELL_W CELL_H BG(RRGGBB) OUT KEYS PROGRAM [ARGS...] */
#include <poll.h>
#include <pty.h>
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static int delay_ms;          /* the answers' lateness */
static char late[8192];       /* answers on their way */
static size_t nlate, sent;    /* their bytes, and those sent so far */
static double late_at;        /* when the next of them go */
static size_t last_answer;    /* where the last answer begins in late */
static int drip_ms, part_ms;  /* PIXTERM_DRIP, PIXTERM_PART */

static void say(int fd, const char *s)
{
    if (delay_ms > 0) {
        size_t n = strlen(s);
        if (nlate == 0)
            late_at = now_s() + delay_ms / 1e3;
        if (nlate + n <= sizeof late)
            last_answer = nlate, memcpy(late + nlate, s, n), nlate += n;
        return;
    }
    if (write(fd, s, strlen(s)) < 0)
        perror("pixterm: write");
}

/* xterm's default colour of palette entry idx, as RRGGBB. */
static void xterm_hex(int idx, char *out, size_t len)
{
    static const char *const sixteen[16] = {
        "000000", "cd0000", "00cd00", "cdcd00", "0000ee", "cd00cd", "00cdcd", "e5e5e5",
        "7f7f7f", "ff0000", "00ff00", "ffff00", "5c5cff", "ff00ff", "00ffff", "ffffff"};
    static const int level[6] = {0, 95, 135, 175, 215, 255};
    if (idx < 16)
        snprintf(out, len, "%s", sixteen[idx]);
    else if (idx < 232)
        snprintf(out, len, "%02x%02x%02x", level[(idx - 16) / 36], level[(idx - 16) / 6 % 6],
                 level[(idx - 16) % 6]);
    else
        snprintf(out, len, "%02x%02x%02x", 8 + 10 * (idx - 232), 8 + 10 * (idx - 232),
                 8 + 10 * (idx - 232));
}

/* The colour of entry key ("27", "fg") as an OSC answer's "rgb:RRRR/GGGG/BBBB" into
 * out: PIXTERM_PALETTE's, else xterm's; false when PIXTERM_PALETTE is "none". */
static bool palette_rgb(const char *key, char *out, size_t len)
{
    const char *pal = getenv("PIXTERM_PALETTE");
    char hex[8];
    size_t k = strlen(key);
    if (pal && strcmp(pal, "none") == 0)
        return false;
    if (strcmp(key, "fg") == 0)
        snprintf(hex, sizeof hex, "000000");
    else
        xterm_hex(atoi(key) & 255, hex, sizeof hex);
    for (const char *p = pal; p && *p; p = strchr(p, ',') ? strchr(p, ',') + 1 : NULL)
        if (strncmp(p, key, k) == 0 && p[k] == '=' && strlen(p + k + 1) >= 6)
            snprintf(hex, sizeof hex, "%.6s", p + k + 1);
    snprintf(out, len, "rgb:%.2s%.2s/%.2s%.2s/%.2s%.2s", hex, hex, hex + 2, hex + 2, hex + 4,
             hex + 4);
    return true;
}

/* Answers each query in what the program wrote (its queries come in one write). */
static void answer(int fd, const char *kind, const char *tail, int cw, int ch, int cols,
                   int rows, const char *bg)
{
    char buf[128];
    bool none = strncmp(kind, "none", 4) == 0, sixel = strncmp(kind, "sixel", 5) == 0,
         kitty = strncmp(kind, "kitty", 5) == 0;
    int registers = strchr(kind, '/') ? atoi(strchr(kind, '/') + 1) : 0;
    if (none)
        return;
    /* In the order asked. */
    const char *q = tail;
    while ((q = strchr(q, '\033'))) {
        if (strncmp(q, "\033_Gi=31,", 8) == 0 && kitty) {
            say(fd, "\033_Gi=31;OK\033\\");
        } else if (strncmp(q, "\033[16t", 5) == 0) {
            snprintf(buf, sizeof buf, "\033[6;%d;%dt", ch, cw);
            say(fd, buf);
        } else if (strncmp(q, "\033[14t", 5) == 0) {
            snprintf(buf, sizeof buf, "\033[4;%d;%dt", ch * rows, cw * cols);
            say(fd, buf);
        } else if (strncmp(q, "\033]11;?", 6) == 0) {
            snprintf(buf, sizeof buf, "\033]11;rgb:%.2s%.2s/%.2s%.2s/%.2s%.2s\033\\", bg, bg,
                     bg + 2, bg + 2, bg + 4, bg + 4);
            say(fd, buf);
        } else if (strncmp(q, "\033]10;?", 6) == 0) {
            char rgb[40];
            if (palette_rgb("fg", rgb, sizeof rgb)) {
                snprintf(buf, sizeof buf, "\033]10;%s\033\\", rgb);
                say(fd, buf);
            }
        } else if (strncmp(q, "\033]4;", 4) == 0) {
            /* "4;N;?;M;?...": each entry it knows, an answer of its own, as xterm does. */
            const char *p = q + 3;
            while (*p == ';') {
                char key[8], rgb[40];
                int idx = atoi(p + 1), used = 0;
                if (sscanf(p + 1, "%*d;?%n", &used) < 0 || used == 0)
                    break;
                snprintf(key, sizeof key, "%d", idx);
                if (palette_rgb(key, rgb, sizeof rgb)) {
                    snprintf(buf, sizeof buf, "\033]4;%d;%s\033\\", idx, rgb);
                    say(fd, buf);
                }
                p += 1 + used;
            }
        } else if (strncmp(q, "\033[?1;1;0S", 9) == 0 && registers > 0) {
            snprintf(buf, sizeof buf, "\033[?1;0;%dS", registers);
            say(fd, buf);
        } else if (strncmp(q, "\033[c", 3) == 0) {
            say(fd, sixel ? "\033[?63;1;2;4;6;9;15;22c" : "\033[?62;1;2;6;9;15;22c");
        }
        q++;
    }
}

int main(int argc, char **argv)
{
    if (argc < 10) {
        fprintf(stderr, "usage: pixterm KIND COLS ROWS CELL_W CELL_H BG OUT KEYS PROGRAM...\n");
        return 2;
    }
    const char *kind = argv[1], *bg = argv[6], *keys = argv[8];
    int cols = atoi(argv[2]), rows = atoi(argv[3]), cw = atoi(argv[4]), ch = atoi(argv[5]);
    if (strchr(kind, '+'))
        delay_ms = atoi(strchr(kind, '+') + 1);
    drip_ms = getenv("PIXTERM_DRIP") ? atoi(getenv("PIXTERM_DRIP")) : 0;
    part_ms = getenv("PIXTERM_PART") ? atoi(getenv("PIXTERM_PART")) : 0;
    char early = 0;
    if (keys[0] == '^' && keys[1])
        early = keys[1], keys += 2;
    FILE *out = fopen(argv[7], "wb");
    if (!out) {
        perror(argv[7]);
        return 1;
    }
    /* No pixel size in the window size: the program has to ask (CSI 16 t). */
    struct winsize ws = {(unsigned short)rows, (unsigned short)cols, 0, 0};
    int fd;
    pid_t pid = forkpty(&fd, NULL, NULL, &ws);
    if (pid < 0) {
        perror("forkpty");
        return 1;
    }
    if (pid == 0) {
        const char *term = getenv("PIXTERM_TERM");
        setenv("TERM", term && *term ? term : "xterm-256color", 1);
        unsetenv("TMUX");
        unsetenv("STY");
        execvp(argv[9], argv + 9);
        _exit(127);
    }
    double start = now_s(), next_key = start + 1.0;
    const char *k = keys;
    for (;;) {
        double t = now_s();
        if (t - start > 30.0) {
            kill(pid, SIGTERM);
            break;
        }
        if (*k && t >= next_key) {
            if (*k == '~') {
                next_key = t + 1.0;
            } else if (k[0] == '\\' && k[1] == 'e') {
                say(fd, "\033");
                k++;
                next_key = t + 0.3;
            } else {
                char c[2] = {*k, 0};
                say(fd, c);
                next_key = t + 0.3;
            }
            k++;
        }
        if (nlate > sent && t >= late_at) {
            /* all at once, a byte at a time (PIXTERM_DRIP), or in two parts (PIXTERM_PART) */
            size_t n = nlate - sent;
            if (drip_ms > 0)
                n = 1, late_at = t + drip_ms / 1e3;
            else if (part_ms > 0 && sent < last_answer + 4)
                n = last_answer + 4 - sent, late_at = t + part_ms / 1e3;
            if (write(fd, late + sent, n) < 0)
                perror("pixterm: write");
            sent += n;
            if (sent == nlate)
                nlate = sent = 0;
        }
        struct pollfd p = {fd, POLLIN, 0};
        if (poll(&p, 1, 5) <= 0)
            continue;
        char buf[65536 + 256];
        ssize_t r = read(fd, buf, 65536);
        if (r <= 0)
            break; /* the program ended */
        fwrite(buf, 1, (size_t)r, out);
        buf[r] = '\0';
        for (ssize_t i = 0; i < r; i++)
            if (buf[i] == '\0')
                buf[i] = ' ';
        if (early && strstr(buf, "\033[c")) {
            if (write(fd, &early, 1) < 0)
                perror("pixterm: write");
            early = 0;
        }
        answer(fd, kind, buf, cw, ch, cols, rows, bg);
    }
    int status = 0;
    struct rusage ru;
    memset(&ru, 0, sizeof ru);
    wait4(pid, &status, 0, &ru);
    /* PIXTERM_RSS=FILE: the program's peak resident memory (kB) written there. */
    const char *rss = getenv("PIXTERM_RSS");
    FILE *rf = rss ? fopen(rss, "w") : NULL;
    if (rf) {
        fprintf(rf, "%ld\n", ru.ru_maxrss);
        fclose(rf);
    }
    fclose(out);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}
