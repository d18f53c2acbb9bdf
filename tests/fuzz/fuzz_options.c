/* fuzz_options.c: libFuzzer target for the option parser: the bytes split at NUL and
 * newline into an argv, parsed as the command line, then the model built from it. */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/config.h"
#include "options.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc, (void)argv;
    /* A preset path such as /dev/stdin must not wait for input; the program's own
     * messages (help, errors) go nowhere, the fuzzer's reports still to stderr. */
    FILE *null = fopen("/dev/null", "w");
    if (!freopen("/dev/null", "r", stdin) || !freopen("/dev/null", "w", stdout) || !null)
        abort();
    options_set_errors(null);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static struct config c;
    static struct cli cli;
    enum { MAX_ARGS = 64 };
    char *buf = malloc(size + 1), *argv[MAX_ARGS + 2];
    int argc = 0;
    if (!buf)
        return 0;
    memcpy(buf, data, size);
    buf[size] = '\0';
    argv[argc++] = (char *)"springsim";
    char *p = buf, *end = buf + size;
    while (p <= end && argc < MAX_ARGS) {
        char *q = p;
        while (q < end && *q != '\0' && *q != '\n')
            q++;
        *q = '\0';
        argv[argc++] = p;
        p = q + 1;
    }
    argv[argc] = NULL;
    config_init(&c);
    memset(&cli, 0, sizeof cli);
    if (options_parse(argc, argv, &c, &cli, "/nonexistent") < 0) {
        int bad;
        char err[512];
        model_free(config_model(&c, &bad, err, sizeof err));
    }
    free(buf);
    return 0;
}
