/* bench_tty.c: the interactive program in a pseudo-terminal of a given size, running
 * for a given time after one press of space, as a person would start it: time to the
 * first frame, CPU share, bytes written to the terminal per second, peak resident
 * memory. Prints one table row. The terminal answers the program's start-up queries as
 * BENCH_TERM says: vt220 (the default: device attributes without sixel, so braille),
 * sixel or kitty (images; cells of 10 x 20 pixels, a white background), or none (it
 * never answers: the program draws braille at once and keeps it).
 * usage: bench_tty COLS ROWS SECONDS LABEL PROGRAM [ARGS...] */
#include <errno.h>
#include <poll.h>
#include <stdbool.h>
#include <pty.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* utime + stime of pid in seconds, from /proc. */
static double cpu_s(pid_t pid)
{
    char path[64], buf[1024];
    snprintf(path, sizeof path, "/proc/%d/stat", (int)pid);
    FILE *f = fopen(path, "r");
    if (!f)
        return 0.0;
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    char *p = strrchr(buf, ')');
    unsigned long ut = 0, st = 0;
    if (p)
        sscanf(p + 2, "%*c %*d %*d %*d %*d %*d %*u %*u %*u %*u %*u %lu %lu", &ut, &st);
    return (double)(ut + st) / (double)sysconf(_SC_CLK_TCK);
}

/* VmHWM of pid in kB. */
static long peak_kb(pid_t pid)
{
    char path[64], line[256];
    long kb = 0;
    snprintf(path, sizeof path, "/proc/%d/status", (int)pid);
    FILE *f = fopen(path, "r");
    while (f && fgets(line, sizeof line, f))
        if (sscanf(line, "VmHWM: %ld", &kb) == 1)
            break;
    if (f)
        fclose(f);
    return kb;
}

static const char *term_kind = "vt220";

/* Answers the queries in what the program wrote, as a terminal of term_kind. */
static void answer(int fd, const char *buf, size_t n)
{
    bool sixel = strcmp(term_kind, "sixel") == 0, kitty = strcmp(term_kind, "kitty") == 0;
    if (strcmp(term_kind, "none") == 0)
        return;
    for (const char *q = buf; (q = memchr(q, '\033', (size_t)(buf + n - q))); q++) {
        const char *a = NULL;
        size_t left = (size_t)(buf + n - q);
        if (left >= 8 && memcmp(q, "\033_Gi=31,", 8) == 0 && kitty)
            a = "\033_Gi=31;OK\033\\";
        else if (left >= 5 && memcmp(q, "\033[16t", 5) == 0)
            a = "\033[6;20;10t";
        else if (left >= 6 && memcmp(q, "\033]11;?", 6) == 0)
            a = "\033]11;rgb:ffff/ffff/ffff\033\\";
        else if (left >= 3 && memcmp(q, "\033[c", 3) == 0)
            a = sixel ? "\033[?63;1;2;4;6;9;15;22c" : "\033[?62;1;2;6;9;15;22c";
        if (a && write(fd, a, strlen(a)) < 0)
            return;
    }
}

/* Reads what the terminal gets until the deadline; counts the bytes; with want, stops
 * as soon as that text has arrived (it may span reads: a small tail is kept). */
static long pump(int fd, double until, const char *want, double *seen_at)
{
    char buf[65536], tail[256 + 65536];
    size_t keep = 0;
    long total = 0;
    while (now_s() < until) {
        struct pollfd p = {fd, POLLIN, 0};
        int ms = (int)((until - now_s()) * 1000.0);
        if (poll(&p, 1, ms > 0 ? ms : 0) <= 0)
            continue;
        ssize_t r = read(fd, buf, sizeof buf);
        if (r <= 0)
            break;
        total += r;
        answer(fd, buf, (size_t)r);
        if (want) {
            memcpy(tail + keep, buf, (size_t)r);
            size_t len = keep + (size_t)r;
            tail[len] = '\0';
            if (memmem(tail, len, want, strlen(want))) {
                *seen_at = now_s();
                return total;
            }
            keep = len < 128 ? len : 128;
            memmove(tail, tail + len - keep, keep);
        }
    }
    return total;
}

int main(int argc, char **argv)
{
    if (argc < 6) {
        fprintf(stderr, "usage: bench_tty COLS ROWS SECONDS LABEL PROGRAM [ARGS...]\n");
        return 2;
    }
    struct winsize ws = {(unsigned short)atoi(argv[2]), (unsigned short)atoi(argv[1]), 0, 0};
    if (getenv("BENCH_TERM"))
        term_kind = getenv("BENCH_TERM");
    double secs = atof(argv[3]);
    int fd;
    double t0 = now_s();
    pid_t pid = forkpty(&fd, NULL, NULL, &ws);
    if (pid < 0) {
        perror("forkpty");
        return 1;
    }
    if (pid == 0) {
        setenv("TERM", "xterm-256color", 1);
        setenv("LANG", "C.UTF-8", 1);
        unsetenv("LC_ALL");
        unsetenv("NO_COLOR");
        execv(argv[5], argv + 5);
        _exit(127);
    }
    double first = 0.0;
    pump(fd, t0 + 5.0, "Controls", &first);
    pump(fd, now_s() + 0.5, NULL, NULL); /* settle */
    /* The keys a person would press: space, or what BENCH_KEYS says (e.g. "1 " to
     * enlarge the displacement plot first). */
    const char *keys = getenv("BENCH_KEYS") ? getenv("BENCH_KEYS") : " ";
    if (write(fd, keys, strlen(keys)) != (ssize_t)strlen(keys))
        return 1;
    double c0 = cpu_s(pid), w0 = now_s();
    long bytes = pump(fd, w0 + secs, NULL, NULL);
    double c1 = cpu_s(pid), w1 = now_s();
    long kb = peak_kb(pid);
    if (write(fd, "q", 1) != 1)
        kill(pid, SIGTERM);
    pump(fd, now_s() + 1.0, NULL, NULL);
    int status;
    waitpid(pid, &status, 0);
    printf("| %s | %dx%d | %.2f %% | %.1f KB/s | %.1f ms | %.1f MB |\n", argv[4], ws.ws_col,
           ws.ws_row, 100.0 * (c1 - c0) / (w1 - w0), bytes / (w1 - w0) / 1024.0,
           first > 0 ? 1000.0 * (first - t0) : -1.0, kb / 1024.0);
    return 0;
}
