/* bench_procs.c: whole processes timed side by side (make bench). Each command is run
 * ROUNDS times, the commands alternated, its output thrown away; the CPU time (user +
 * system, from wait4) of each is kept and the medians printed, each with its ratio to the
 * first command's (how many times longer it takes), alternated so that a busy machine
 * slows every side alike. BENCH_ROUNDS in the environment takes more rounds (at most
 * MAX_ROUNDS) where the machine's speed drifts.
 * Usage: bench_procs LABEL -- CMD ARGS... [-- LABEL -- CMD ARGS...]... */
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#define ROUNDS 5
#define MAX_ROUNDS 51
#define MAX_CMDS 8

struct cmd {
    const char *label;
    char **argv;
    double cpu[MAX_ROUNDS];
};

static int compare(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* CPU seconds the command took, or -1 when it could not run or failed. */
static double run(char **argv)
{
    pid_t pid = fork();
    if (pid < 0)
        return -1.0;
    if (pid == 0) {
        int null = open("/dev/null", O_WRONLY);
        if (null >= 0)
            dup2(null, STDOUT_FILENO);
        execvp(argv[0], argv);
        _exit(127);
    }
    int status;
    struct rusage ru;
    if (wait4(pid, &status, 0, &ru) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return -1.0;
    return (double)ru.ru_utime.tv_sec + 1e-6 * (double)ru.ru_utime.tv_usec +
           (double)ru.ru_stime.tv_sec + 1e-6 * (double)ru.ru_stime.tv_usec;
}

int main(int argc, char **argv)
{
    struct cmd cmds[MAX_CMDS];
    int count = 0;
    for (int i = 1; i < argc && count < MAX_CMDS;) {
        if (i + 2 >= argc || strcmp(argv[i + 1], "--") != 0)
            return 2;
        cmds[count].label = argv[i];
        cmds[count].argv = argv + i + 2;
        int j = i + 2;
        while (j < argc && strcmp(argv[j], "--") != 0)
            j++;
        argv[j < argc ? j : argc] = NULL; /* ends this command's words */
        count++;
        i = j + 1;
    }
    if (count == 0)
        return 2;
    const char *want = getenv("BENCH_ROUNDS");
    int rounds = want ? atoi(want) : ROUNDS;
    if (rounds < 1 || rounds > MAX_ROUNDS)
        rounds = ROUNDS;
    for (int r = 0; r < rounds; r++)
        for (int c = 0; c < count; c++)
            if ((cmds[c].cpu[r] = run(cmds[c].argv)) < 0.0) {
                fprintf(stderr, "bench_procs: %s failed\n", cmds[c].label);
                return 1;
            }
    double first = 0.0;
    for (int c = 0; c < count; c++) {
        qsort(cmds[c].cpu, (size_t)rounds, sizeof *cmds[c].cpu, compare);
        double med = cmds[c].cpu[rounds / 2];
        if (c == 0)
            first = med;
        printf("| %s | %.3f s | %.2fx |\n", cmds[c].label, med, first > 0.0 ? med / first : 0.0);
    }
    return 0;
}
