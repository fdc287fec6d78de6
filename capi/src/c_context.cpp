// The C API's context, errors and image comparison (hush.h).
#include <cstring>
#include <string>

#include "c_api_guard.hpp"
#include "c_objects.hpp"

namespace hush::capi {
namespace {
thread_local std::string lastError;
}

void setLastError(const std::string& message) { lastError = message; }
void clearLastError() { lastError.clear(); }

void badArgument(const char* argument, const std::string& why) {
    throw Error(ErrorKind::InvalidArgument, std::string("argument '") + argument + "' " + why);
}

HushStatus statusOf(ErrorKind kind) {
    switch (kind) {
    case ErrorKind::InvalidArgument: return HUSH_ERROR_INVALID_ARGUMENT;
    case ErrorKind::NotFound: return HUSH_ERROR_NOT_FOUND;
    case ErrorKind::Unsupported: return HUSH_ERROR_UNSUPPORTED;
    case ErrorKind::OutOfMemory: return HUSH_ERROR_OUT_OF_MEMORY;
    case ErrorKind::Io: return HUSH_ERROR_IO;
    case ErrorKind::NoLoader:
    case ErrorKind::NoDriver:
    case ErrorKind::NoAdapter: return HUSH_ERROR_NO_DEVICE;
    case ErrorKind::DeviceLost: return HUSH_ERROR_DEVICE_LOST;
    case ErrorKind::Driver: return HUSH_ERROR_DRIVER;
    case ErrorKind::BindingMismatch: return HUSH_ERROR_INTERNAL;
    }
    return HUSH_ERROR_INTERNAL;
}

} // namespace hush::capi

using namespace hush;
using capi::guarded;
using capi::required;

extern "C" {

HUSH_API const char* hushLastError(void) { return capi::lastError.c_str(); }

HUSH_API int hushApiVersion(void) { return HUSH_C_API_VERSION; }

HUSH_API const char* hushStatusName(HushStatus status) {
    switch (status) {
    case HUSH_SUCCESS: return "success";
    case HUSH_ERROR_INVALID_ARGUMENT: return "invalid-argument";
    case HUSH_ERROR_NOT_FOUND: return "not-found";
    case HUSH_ERROR_UNSUPPORTED: return "unsupported";
    case HUSH_ERROR_OUT_OF_MEMORY: return "out-of-memory";
    case HUSH_ERROR_IO: return "io";
    case HUSH_ERROR_NO_DEVICE: return "no-device";
    case HUSH_ERROR_DEVICE_LOST: return "device-lost";
    case HUSH_ERROR_DRIVER: return "driver";
    case HUSH_ERROR_INTERNAL: return "internal";
    }
    return "unknown-status";
}

HUSH_API HushStatus hushCreateContext(const HushContextDesc* desc, HushContext* context) {
    return guarded("hushCreateContext", [&] {
        required(context, "context");
        *context = nullptr;
        const HushContextDesc defaults{};
        if (!desc) desc = &defaults;
        auto made = std::make_unique<HushContext_T>();
        rhi::InstanceDesc instanceDesc;
        if (desc->validation) instanceDesc.validation = true, instanceDesc.validationFromEnvironment = false;
        made->instance = rhi::Instance::create(instanceDesc);
        rhi::AdapterRequest request;
        if (desc->adapter && *desc->adapter) request.nameContains = desc->adapter, request.nameFromEnvironment = false;
        const rhi::Adapter adapter = made->instance->requestAdapter(request);
        made->adapterName = adapter.info().name;
        made->device = adapter.createDevice({.label = "hush-c"});
        *context = made.release();
    });
}

HUSH_API void hushDestroyContext(HushContext context) { delete context; }

HUSH_API const char* hushContextAdapterName(HushContext context) {
    return context ? context->adapterName.c_str() : "";
}

HUSH_API size_t hushContextValidationMessageCount(HushContext context) {
    return context && context->instance ? context->instance->validationMessageCount() : 0;
}

HUSH_API HushStatus hushCompareImages(HushContext context, const float* image, const float* reference, uint32_t width,
                                      uint32_t height, HushQuality* quality) {
    return guarded("hushCompareImages", [&] {
        required(context, "context");
        required(image, "image");
        required(reference, "reference");
        required(quality, "quality");
        if (width == 0 || height == 0) capi::badArgument("width", "and 'height' must be positive");
        const rhi::Extent2D size{width, height};
        if (!context->metrics || context->metrics->size().width != width || context->metrics->size().height != height)
            context->metrics = std::make_unique<passes::MetricsEvaluator>(context->device, size);
        const size_t count = size_t(width) * height * 4;
        const passes::ImageMetrics m = context->metrics->compare({image, count}, {reference, count});
        *quality = {m.rmse, m.relMse, m.psnr, m.ssim};
    });
}

} // extern "C"
