/* fuzz_preset.c: libFuzzer target for the preset reader: any bytes as a preset file,
 * then the model built from it. It must never crash, hang or leak. */
#include <stddef.h>
#include <stdint.h>

#include "core/config.h"
#include "core/preset.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static struct config c;
    char err[1024];
    int bad;
    config_init(&c);
    if (preset_parse("fuzz.ini", (const char *)data, size, &c, err, sizeof err) == PRESET_OK) {
        struct model *m = config_model(&c, &bad, err, sizeof err);
        model_free(m);
    }
    return 0;
}
