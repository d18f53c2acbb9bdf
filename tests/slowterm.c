/* slowterm.c: a terminal that stops reading. Runs the interactive program in a
 * pseudo-terminal, starts it, then reads nothing for a while, as a stalled SSH link
 * would: a stall of 1 s (a busy machine, a hiccup) changes nothing; one of 4 s makes the
 * program notice its output backing up, step down to low bandwidth on its own and say
 * so; once the terminal reads again and keeps up (12 s), it steps back up and says so.
 * Prints "slowterm: N passed, M failed".
 * usage: slowterm PROGRAM */
#include <poll.h>
#include <pty.h>
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static char screen[1 << 22];
static size_t have;

/* Reads for ms milliseconds, keeping what arrives. */
static void drain(int fd, int ms)
{
    struct timespec start, now;
    clock_gettime(CLOCK_MONOTONIC, &start);
    for (;;) {
        clock_gettime(CLOCK_MONOTONIC, &now);
        long spent = (now.tv_sec - start.tv_sec) * 1000 + (now.tv_nsec - start.tv_nsec) / 1000000;
        if (spent >= ms)
            return;
        struct pollfd p = {fd, POLLIN, 0};
        if (poll(&p, 1, (int)(ms - spent)) <= 0)
            continue;
        char buf[65536];
        ssize_t r = read(fd, buf, sizeof buf);
        if (r <= 0)
            return;
        if (have + (size_t)r >= sizeof screen)
            have = 0; /* only the newest output matters */
        memcpy(screen + have, buf, (size_t)r);
        have += (size_t)r;
    }
}

int main(int argc, char **argv)
{
    int passed = 0, failed = 0, fd;
    struct winsize ws = {60, 200, 0, 0};
    if (argc < 2)
        return 2;
    pid_t pid = forkpty(&fd, NULL, NULL, &ws);
    if (pid == 0) {
        setenv("TERM", "xterm-256color", 1);
        setenv("LANG", "C.UTF-8", 1);
        unsetenv("NO_COLOR");
        execv(argv[1], argv + 1);
        _exit(127);
    }
    drain(fd, 1000);
    if (write(fd, " ", 1) != 1)
        return 1;
    drain(fd, 300);
    /* A hiccup: 1 s without reading, then reading again. */
    sleep(1);
    drain(fd, 1500);
    have = 0;
    if (write(fd, "\f", 1) != 1)
        return 1;
    drain(fd, 800);
    if (memmem(screen, have, "Running", 7) && !memmem(screen, have, "keeping", 7) &&
        !memmem(screen, have, "low refresh", 11)) {
        passed++;
    } else {
        failed++;
        printf("FAIL: a terminal that stopped reading for 1 s only: the program stepped down "
               "(or is not running)\n");
    }
    have = 0;
    sleep(4); /* the link stalls: nothing is read */
    drain(fd, 1500);
    /* Ask for a whole new screen (Ctrl-L), so the words arrive whole rather than as the
     * few cells that changed. */
    have = 0;
    if (write(fd, "\f", 1) != 1)
        return 1;
    drain(fd, 800);
    if (memmem(screen, have, "keeping", 7) && memmem(screen, have, "low refresh", 11)) {
        passed++;
    } else {
        failed++;
        printf("FAIL: a terminal that stopped reading for 4 s: no step-down to low bandwidth "
               "was shown (keeping: %s, low refresh: %s)\n",
               memmem(screen, have, "keeping", 7) ? "yes" : "no",
               memmem(screen, have, "low refresh", 11) ? "yes" : "no");
        FILE *f = getenv("SLOWTERM_DUMP") ? fopen(getenv("SLOWTERM_DUMP"), "w") : NULL;
        if (f) {
            fwrite(screen, 1, have, f);
            fclose(f);
        }
    }
    /* The link keeps up again: back to the normal refresh, said. */
    have = 0;
    drain(fd, 12000);
    bool said = memmem(screen, have, "keeps up again", 14) != NULL;
    have = 0;
    if (write(fd, "\f", 1) != 1)
        return 1;
    drain(fd, 800);
    if (said && !memmem(screen, have, "low refresh", 11) && memmem(screen, have, "Running", 7)) {
        passed++;
    } else {
        failed++;
        printf("FAIL: the terminal read again for 12 s: no step back up (said: %s, low "
               "refresh still shown: %s)\n", said ? "yes" : "no",
               memmem(screen, have, "low refresh", 11) ? "yes" : "no");
    }
    /* Still alive and answering. */
    int status = 0, done = 0;
    if (write(fd, "q", 1) == 1)
        for (int i = 0; i < 50 && !done; i++) { /* keep reading: it must not block */
            drain(fd, 100);
            usleep(20000); /* once the terminal is closed, reads return at once */
            done = waitpid(pid, &status, WNOHANG) == pid;
        }
    if (done && WIFEXITED(status) && WEXITSTATUS(status) == 0) {
        passed++;
    } else {
        failed++;
        printf("FAIL: q after the stall did not end the program with status 0 (%s, status %d)\n", done ? "ended" : "still running", status);
        kill(pid, SIGKILL);
        waitpid(pid, &status, 0);
    }
    printf("slowterm: %d passed, %d failed\n", passed, failed);
    return failed != 0;
}
