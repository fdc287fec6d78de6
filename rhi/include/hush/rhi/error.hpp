#pragma once
// hush::Error: the one exception type hush throws (header-only: every layer uses it). Its message says what went wrong
// and what to do about it; kind() lets code react without parsing text.
#include <stdexcept>
#include <string>

namespace hush {

enum class ErrorKind {
    NoVulkanLoader,      // libvulkan.so.1 could not be opened
    NoDriver,            // loader present, but no ICD / driver answers
    NoAdapter,           // no physical device, or none matches the request
    Unsupported,         // format, usage, size or feature the adapter lacks
    InvalidArgument,     // a descriptor or call that is wrong whatever the device
    BindingMismatch,     // a bind group that does not match the pipeline's layout
    OutOfMemory,         // host or device memory exhausted
    DeviceLost,          // the driver lost the device; recreate it
    Vulkan,              // any other Vulkan failure
    NotFound,            // a named thing (shader, file, resource) is missing
};

// Inline, so that layers which only throw and report errors (the tracer) need no rhi library.
inline const char* toString(ErrorKind kind) {
    switch (kind) {
    case ErrorKind::NoVulkanLoader: return "no-vulkan-loader";
    case ErrorKind::NoDriver: return "no-driver";
    case ErrorKind::NoAdapter: return "no-adapter";
    case ErrorKind::Unsupported: return "unsupported";
    case ErrorKind::InvalidArgument: return "invalid-argument";
    case ErrorKind::BindingMismatch: return "binding-mismatch";
    case ErrorKind::OutOfMemory: return "out-of-memory";
    case ErrorKind::DeviceLost: return "device-lost";
    case ErrorKind::Vulkan: return "vulkan";
    case ErrorKind::NotFound: return "not-found";
    }
    return "unknown";
}

class Error : public std::runtime_error {
public:
    Error(ErrorKind kind, const std::string& message)
        : std::runtime_error(message), kind_(kind) {}
    ErrorKind kind() const noexcept { return kind_; }

private:
    ErrorKind kind_;
};

} // namespace hush
