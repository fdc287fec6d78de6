/* hush.h: hush's C API, a stable interface over the C++ library that any language can
 * bind. Opaque handles, explicit destroy, no exceptions across the boundary: every
 * call returns a HushStatus, and hushLastError() says what went wrong, naming the
 * argument. docs/c-api.md is the guide; hush_vulkan.h adds an engine's own VkDevice
 * and VkImages.
 *
 * A frame:  create a context, a denoiser for a chain and a size; each frame set the
 * inputs the chain reads (hushDenoiserInput lists them) and the camera, execute, read
 * the output. Not thread-safe per handle: one thread at a time per context and its
 * denoisers. */
#ifndef HUSH_HUSH_H
#define HUSH_HUSH_H

#include <stddef.h>
#include <stdint.h>

#if defined(_WIN32)
#define HUSH_API __declspec(dllimport)
#elif defined(HUSH_C_BUILD)
#define HUSH_API __attribute__((visibility("default")))
#else
#define HUSH_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

#define HUSH_C_API_VERSION 1

typedef enum HushStatus {
    HUSH_SUCCESS = 0,
    HUSH_ERROR_INVALID_ARGUMENT = 1, /* a null pointer, a wrong size, an unknown name, a bad chain file */
    HUSH_ERROR_NOT_FOUND = 2,        /* a named file, layer or input is missing */
    HUSH_ERROR_UNSUPPORTED = 3,      /* a format, size or feature the device lacks */
    HUSH_ERROR_OUT_OF_MEMORY = 4,
    HUSH_ERROR_IO = 5,               /* the file system refused */
    HUSH_ERROR_NO_DEVICE = 6,        /* no Vulkan loader, driver or adapter */
    HUSH_ERROR_DEVICE_LOST = 7,      /* destroy the context and create a new one */
    HUSH_ERROR_DRIVER = 8,           /* any other failure the driver reports */
    HUSH_ERROR_INTERNAL = 9          /* a bug in hush: please report the message */
} HushStatus;

typedef struct HushContext_T* HushContext;
typedef struct HushDenoiser_T* HushDenoiser;

/* The message of the last failed call on this thread ("" if none), valid until the
 * next call on this thread. Names the argument, file, layer or setting at fault. */
HUSH_API const char* hushLastError(void);
HUSH_API const char* hushStatusName(HushStatus status); /* "invalid-argument", ... */
HUSH_API int hushApiVersion(void);                       /* HUSH_C_API_VERSION of the library */

/* ---- context: a Vulkan device hush owns (hush_vulkan.h: or the engine's) ---- */

typedef struct HushContextDesc {
    const char* adapter; /* NULL or "": HUSH_ADAPTER, else discrete, integrated, any, CPU */
    int validation;      /* non-zero: Vulkan validation with synchronization validation */
} HushContextDesc;

HUSH_API HushStatus hushCreateContext(const HushContextDesc* desc, HushContext* context); /* desc may be NULL */
HUSH_API void hushDestroyContext(HushContext context);                                    /* NULL: no-op */
/* The adapter's name ("llvmpipe (LLVM 15.0.6, 256 bits)"). */
HUSH_API const char* hushContextAdapterName(HushContext context);
/* Validation messages since the context was created (0 without validation). */
HUSH_API size_t hushContextValidationMessageCount(HushContext context);

/* ---- denoiser: one chain at one size, with its history ---- */

typedef struct HushDenoiserDesc {
    const char* chain;     /* a built-in chain: "svgf", "bmfr", "eaw", "mara", "rdae" ... */
    const char* chainJson; /* or a chain file's text (docs/passes/chain-files.md); chain must be NULL */
    uint32_t width, height;
    /* Comma-separated input layers the frames will carry ("color,albedo,normal"); NULL:
     * all. A chain's optional inputs outside it are not read (Mara's glossy term). */
    const char* available;
} HushDenoiserDesc;

HUSH_API HushStatus hushCreateDenoiser(HushContext context, const HushDenoiserDesc* desc, HushDenoiser* denoiser);
HUSH_API void hushDestroyDenoiser(HushDenoiser denoiser); /* NULL: no-op */

/* The inputs the chain reads, by index 0 .. count-1: the frame format's layer name
 * ("color", "motion", ...) and its component count (3 for colours, 2 for motion, ...). */
HUSH_API uint32_t hushDenoiserInputCount(HushDenoiser denoiser);
HUSH_API HushStatus hushDenoiserInput(HushDenoiser denoiser, uint32_t index, const char** name, uint32_t* components);

/* Host-memory input: width * height texels of `components` floats, rows from the top,
 * `rowStrideBytes` apart (0: tightly packed), in the frame format's conventions
 * (docs/frame-format.md; meshid as float, -1 where nothing is hit). Inputs keep their
 * contents between frames; every input must be set before the first execute. */
HUSH_API HushStatus hushSetInput(HushDenoiser denoiser, const char* name, const float* pixels, uint32_t width,
                                 uint32_t height, uint32_t components, size_t rowStrideBytes);

typedef struct HushCamera {
    float view[16];               /* world -> view, column-major (GLM), camera looks down -Z */
    float projection[16];         /* view -> Vulkan clip space (depth 0..1, y down in NDC) */
    float previousView[16];       /* last frame's (this frame's on the first) */
    float previousProjection[16];
    float position[3];            /* world space */
    float metresPerUnit;          /* 0 means 1 */
} HushCamera;
/* The frame's camera (read by Mara's glossy reprojection and the RDAE); identity if never set. */
HUSH_API HushStatus hushSetCamera(HushDenoiser denoiser, const HushCamera* camera);

/* Runs one frame and waits for it. */
HUSH_API HushStatus hushExecute(HushDenoiser denoiser);
/* Forgets the history (a camera cut). */
HUSH_API HushStatus hushResetHistory(HushDenoiser denoiser);

typedef enum HushOutput {
    HUSH_OUTPUT_RADIANCE = 0, /* filtered HDR radiance, before tonemapping */
    HUSH_OUTPUT_DISPLAY = 1   /* tonemapped (and anti-aliased) in [0, 1], linear */
} HushOutput;
/* After execute: width * height * 4 floats (RGBA, rows from the top) into `rgba`,
 * which holds `count` floats. */
HUSH_API HushStatus hushReadOutput(HushDenoiser denoiser, HushOutput output, float* rgba, size_t count);

/* The last executed frame's GPU time per pass, in execution order. index < count. */
HUSH_API uint32_t hushPassCount(HushDenoiser denoiser);
HUSH_API HushStatus hushPassTiming(HushDenoiser denoiser, uint32_t index, const char** name, double* gpuMs);
HUSH_API double hushFrameGpuMs(HushDenoiser denoiser); /* their sum; negative before timings exist */

/* ---- quality: compare two RGBA images (width * height * 4 floats) on the GPU ---- */

typedef struct HushQuality {
    double rmse, relMse, psnr, ssim;
} HushQuality;
HUSH_API HushStatus hushCompareImages(HushContext context, const float* image, const float* reference, uint32_t width,
                                      uint32_t height, HushQuality* quality);

/* ---- frame files (docs/frame-format.md), for tools and tests ---- */

/* The size of a frame file, from its header. */
HUSH_API HushStatus hushFrameFileSize(const char* path, uint32_t* width, uint32_t* height);
/* One layer of a frame file into `pixels` (width * height * components floats, its
 * `components` from hushDenoiserInput or the format's table; `count` floats held). */
HUSH_API HushStatus hushReadFrameLayer(const char* path, const char* layer, float* pixels, size_t count);
/* The file's camera (hush.camera.* and hush.previousCamera.*). */
HUSH_API HushStatus hushReadFrameCamera(const char* path, HushCamera* camera);

#ifdef __cplusplus
}
#endif

#endif /* HUSH_HUSH_H */
