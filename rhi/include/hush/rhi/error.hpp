#pragma once
// hush::Error: the one exception type hush throws. Its message says what went wrong
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

const char* toString(ErrorKind kind);

class Error : public std::runtime_error {
public:
    Error(ErrorKind kind, const std::string& message)
        : std::runtime_error(message), kind_(kind) {}
    ErrorKind kind() const noexcept { return kind_; }

private:
    ErrorKind kind_;
};

} // namespace hush
