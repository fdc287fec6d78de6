/* The C API from C (C11): bad arguments return a status and a message naming the
 * argument, never abort; then SVGF denoises tracer frames read through the API's own
 * frame-file readers, and beats the noisy input against the reference (relative MSE:
 * the HDR radiance of the light would dominate an RMSE).
 * Usage: test_c_api <folder of frames rendered by hush render>   (tests/capi/CMakeLists.txt) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <hush/hush.h>

static int failures = 0;

#define CHECK(condition, ...)                                              \
    do {                                                                   \
        if (!(condition)) {                                                \
            fprintf(stderr, "FAIL %s:%d: %s: ", __FILE__, __LINE__, #condition); \
            fprintf(stderr, __VA_ARGS__);                                  \
            fprintf(stderr, "\n");                                         \
            ++failures;                                                    \
        }                                                                  \
    } while (0)

/* A call that must fail with `status` and a message containing `words`. */
static void expectError(HushStatus got, HushStatus status, const char* words, const char* what) {
    CHECK(got == status, "%s: status %s, expected %s (%s)", what, hushStatusName(got), hushStatusName(status),
          hushLastError());
    CHECK(strstr(hushLastError(), words) != NULL, "%s: message '%s' lacks '%s'", what, hushLastError(), words);
    printf("ok: %s -> %s: %s\n", what, hushStatusName(got), hushLastError());
}

static void framePath(char* out, size_t size, const char* folder, int index) {
    snprintf(out, size, "%s/frame_%04d.exr", folder, index);
}

/* A 3-component layer of a frame file as RGBA (alpha 1), for hushCompareImages. */
static float* readRgba(const char* path, const char* layer, uint32_t width, uint32_t height) {
    const size_t pixels = (size_t)width * height;
    float* rgb = malloc(pixels * 3 * sizeof(float));
    float* rgba = malloc(pixels * 4 * sizeof(float));
    if (!rgb || !rgba) abort();
    HushStatus status = hushReadFrameLayer(path, layer, rgb, pixels * 3);
    CHECK(status == HUSH_SUCCESS, "reading %s of %s: %s", layer, path, hushLastError());
    for (size_t i = 0; i < pixels; ++i) {
        for (int c = 0; c < 3; ++c) rgba[i * 4 + c] = rgb[i * 3 + c];
        rgba[i * 4 + 3] = 1.0f;
    }
    free(rgb);
    return rgba;
}

static void testBadArguments(HushContext context) {
    HushDenoiser denoiser = NULL;
    HushDenoiserDesc desc = {0};
    expectError(hushCreateContext(NULL, NULL), HUSH_ERROR_INVALID_ARGUMENT, "'context'", "context: NULL out-pointer");
    expectError(hushCreateDenoiser(context, NULL, &denoiser), HUSH_ERROR_INVALID_ARGUMENT, "'desc'", "desc: NULL");
    CHECK(denoiser == NULL, "a failed create left a handle");
    desc.chain = "svgff";
    desc.width = desc.height = 16;
    expectError(hushCreateDenoiser(context, &desc, &denoiser), HUSH_ERROR_INVALID_ARGUMENT, "not a built-in chain",
                "unknown chain");
    desc.chain = NULL;
    desc.chainJson = "{\"base\": \"svgf\", \"atrous\": {\"iterations\": }";
    expectError(hushCreateDenoiser(context, &desc, &denoiser), HUSH_ERROR_INVALID_ARGUMENT, "chainJson:1:",
                "chain-file syntax error");
    desc.chainJson = "{\"name\": \"mine\", \"base\": \"svgf\", \"settings\": {\"atrous\": {\"iterations\": 99}}}";
    expectError(hushCreateDenoiser(context, &desc, &denoiser), HUSH_ERROR_INVALID_ARGUMENT, "iterations",
                "chain-file setting out of range");
    desc.chainJson = NULL;
    desc.chain = "eaw";
    desc.width = 0;
    expectError(hushCreateDenoiser(context, &desc, &denoiser), HUSH_ERROR_INVALID_ARGUMENT, "desc->width", "zero width");
    desc.width = 16;
    desc.available = "color,albedoo";
    expectError(hushCreateDenoiser(context, &desc, &denoiser), HUSH_ERROR_INVALID_ARGUMENT, "albedoo", "unknown layer");
    desc.available = NULL;
    CHECK(hushCreateDenoiser(context, &desc, &denoiser) == HUSH_SUCCESS, "eaw 16x16: %s", hushLastError());

    float pixels[16 * 16 * 3] = {0};
    expectError(hushSetInput(denoiser, "color", NULL, 16, 16, 3, 0), HUSH_ERROR_INVALID_ARGUMENT, "'pixels'", "NULL pixels");
    expectError(hushSetInput(denoiser, "color", pixels, 8, 16, 3, 0), HUSH_ERROR_INVALID_ARGUMENT, "'width'", "wrong size");
    expectError(hushSetInput(denoiser, "color", pixels, 16, 16, 4, 0), HUSH_ERROR_INVALID_ARGUMENT, "'components'",
                "wrong component count");
    expectError(hushSetInput(denoiser, "colour", pixels, 16, 16, 3, 0), HUSH_ERROR_INVALID_ARGUMENT, "'colour'",
                "unknown input");
    expectError(hushSetInput(denoiser, "color", pixels, 16, 16, 3, 20), HUSH_ERROR_INVALID_ARGUMENT, "'rowStrideBytes'",
                "stride shorter than a row");
    expectError(hushExecute(denoiser), HUSH_ERROR_NOT_FOUND, "was never set", "execute before the inputs are set");
    float output[16 * 16 * 4];
    expectError(hushReadOutput(denoiser, HUSH_OUTPUT_DISPLAY, output, 16 * 16 * 4), HUSH_ERROR_INVALID_ARGUMENT,
                "no frame was executed", "read before execute");
    expectError(hushExecute(NULL), HUSH_ERROR_INVALID_ARGUMENT, "'denoiser'", "NULL denoiser");
    expectError(hushReadFrameLayer("no-such-file.exr", "color", pixels, 3), HUSH_ERROR_NOT_FOUND, "no-such-file.exr",
                "missing frame file");
    hushDestroyDenoiser(denoiser);
    hushDestroyDenoiser(NULL);
}

/* Denoises the folder's frames with SVGF; returns the last frame's quality of the
 * filtered radiance and of the noisy colour against the reference. */
static void denoiseFrames(HushContext context, const char* folder, HushQuality* denoised, HushQuality* input) {
    char path[4096];
    uint32_t width = 0, height = 0;
    framePath(path, sizeof path, folder, 0);
    CHECK(hushFrameFileSize(path, &width, &height) == HUSH_SUCCESS, "%s", hushLastError());
    HushDenoiserDesc desc = {.chain = "svgf", .width = width, .height = height};
    HushDenoiser denoiser = NULL;
    CHECK(hushCreateDenoiser(context, &desc, &denoiser) == HUSH_SUCCESS, "svgf: %s", hushLastError());
    if (!denoiser) return;
    float* layer = malloc((size_t)width * height * 3 * sizeof(float));
    float* rgba = malloc((size_t)width * height * 4 * sizeof(float));
    if (!layer || !rgba) abort();
    for (int frame = 0; frame < 4; ++frame) {
        framePath(path, sizeof path, folder, frame);
        for (uint32_t i = 0; i < hushDenoiserInputCount(denoiser); ++i) {
            const char* name = NULL;
            uint32_t components = 0;
            CHECK(hushDenoiserInput(denoiser, i, &name, &components) == HUSH_SUCCESS, "%s", hushLastError());
            CHECK(hushReadFrameLayer(path, name, layer, (size_t)width * height * components) == HUSH_SUCCESS, "%s",
                  hushLastError());
            CHECK(hushSetInput(denoiser, name, layer, width, height, components, 0) == HUSH_SUCCESS, "%s", hushLastError());
        }
        HushCamera camera;
        CHECK(hushReadFrameCamera(path, &camera) == HUSH_SUCCESS, "%s", hushLastError());
        CHECK(hushSetCamera(denoiser, &camera) == HUSH_SUCCESS, "%s", hushLastError());
        CHECK(hushExecute(denoiser) == HUSH_SUCCESS, "frame %d: %s", frame, hushLastError());
    }
    CHECK(hushReadOutput(denoiser, HUSH_OUTPUT_RADIANCE, rgba, (size_t)width * height * 4) == HUSH_SUCCESS, "%s",
          hushLastError());
    for (size_t i = 0; i < (size_t)width * height * 4; ++i) CHECK(isfinite(rgba[i]), "non-finite output at %zu", i);
    float* reference = readRgba(path, "reference", width, height);
    float* noisy = readRgba(path, "color", width, height);
    CHECK(hushCompareImages(context, rgba, reference, width, height, denoised) == HUSH_SUCCESS, "%s", hushLastError());
    CHECK(hushCompareImages(context, noisy, reference, width, height, input) == HUSH_SUCCESS, "%s", hushLastError());
    CHECK(hushPassCount(denoiser) > 0, "no pass timings");
    for (uint32_t i = 0; i < hushPassCount(denoiser); ++i) {
        const char* name = NULL;
        double ms = -1.0;
        CHECK(hushPassTiming(denoiser, i, &name, &ms) == HUSH_SUCCESS && name && ms >= 0.0, "pass %u", i);
    }
    printf("svgf through the C API: %ux%u, %u passes, %.3f GPU ms per frame\n", width, height,
           hushPassCount(denoiser), hushFrameGpuMs(denoiser));
    free(reference);
    free(noisy);
    free(layer);
    free(rgba);
    hushDestroyDenoiser(denoiser);
}

int main(int argc, char** argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: test_c_api <folder of frames>\n");
        return 2;
    }
    CHECK(hushApiVersion() == HUSH_C_API_VERSION, "library version %d, header %d", hushApiVersion(), HUSH_C_API_VERSION);
    HushContextDesc contextDesc = {.adapter = NULL, .validation = 1};
    HushContext context = NULL;
    if (hushCreateContext(&contextDesc, &context) != HUSH_SUCCESS) {
        fprintf(stderr, "FAIL: no context: %s\n", hushLastError());
        return 1;
    }
    printf("adapter: %s\n", hushContextAdapterName(context));
    testBadArguments(context);
    HushQuality denoised = {0}, noisy = {0};
    denoiseFrames(context, argv[1], &denoised, &noisy);
    printf("against the reference, last frame: relative MSE noisy %.5f, svgf %.5f; RMSE noisy %.5f, svgf %.5f\n",
           noisy.relMse, denoised.relMse, noisy.rmse, denoised.rmse);
    CHECK(denoised.relMse > 0.0 && denoised.relMse < 0.5 * noisy.relMse, "svgf %.5f does not halve the input's %.5f",
          denoised.relMse, noisy.relMse);
    CHECK(hushContextValidationMessageCount(context) == 0, "%zu validation messages",
          hushContextValidationMessageCount(context));
    hushDestroyContext(context);
    hushDestroyContext(NULL);
    if (failures) fprintf(stderr, "%d check(s) failed\n", failures);
    else printf("all C API checks passed\n");
    return failures ? 1 : 0;
}
