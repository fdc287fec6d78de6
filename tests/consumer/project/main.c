/* The C API as an outside C project uses it (CMake's hush::c or pkg-config): EAW on a
 * tiny constant frame must give back that constant, with no validation message. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <hush/hush.h>

#define SIZE 8

static int fail(const char* what) {
    fprintf(stderr, "hush C consumer: FAIL: %s: %s\n", what, hushLastError());
    return 1;
}

int main(void) {
    HushContextDesc contextDesc = {NULL, 1};
    HushContext context = NULL;
    if (hushCreateContext(&contextDesc, &context) != HUSH_SUCCESS) return fail("context");
    HushDenoiserDesc desc;
    memset(&desc, 0, sizeof desc);
    desc.chain = "eaw";
    desc.width = desc.height = SIZE;
    HushDenoiser denoiser = NULL;
    if (hushCreateDenoiser(context, &desc, &denoiser) != HUSH_SUCCESS) return fail("denoiser");
    static float layer[SIZE * SIZE * 3];
    for (uint32_t i = 0; i < hushDenoiserInputCount(denoiser); ++i) {
        const char* name = NULL;
        uint32_t components = 0;
        if (hushDenoiserInput(denoiser, i, &name, &components) != HUSH_SUCCESS) return fail("input");
        for (int p = 0; p < SIZE * SIZE; ++p)
            for (uint32_t c = 0; c < components; ++c)
                layer[p * components + c] = strcmp(name, "normal") == 0 ? (c == 2 ? 1.0f : 0.0f)
                                            : strcmp(name, "emission") == 0 ? 0.0f
                                            : strcmp(name, "depth") == 0 ? 2.0f
                                                                          : 0.5f;
        if (hushSetInput(denoiser, name, layer, SIZE, SIZE, components, 0) != HUSH_SUCCESS) return fail(name);
    }
    if (hushExecute(denoiser) != HUSH_SUCCESS) return fail("execute");
    static float radiance[SIZE * SIZE * 4];
    if (hushReadOutput(denoiser, HUSH_OUTPUT_RADIANCE, radiance, SIZE * SIZE * 4) != HUSH_SUCCESS) return fail("read");
    for (int p = 0; p < SIZE * SIZE; ++p)
        if (fabsf(radiance[p * 4] - 0.5f) > 1e-4f) {
            fprintf(stderr, "hush C consumer: FAIL: pixel %d is %g, not 0.5\n", p, radiance[p * 4]);
            return 1;
        }
    const size_t messages = hushContextValidationMessageCount(context);
    hushDestroyDenoiser(denoiser);
    hushDestroyContext(context);
    if (messages) {
        fprintf(stderr, "hush C consumer: FAIL: %zu validation messages\n", messages);
        return 1;
    }
    printf("hush C consumer: PASS\n");
    return 0;
}
