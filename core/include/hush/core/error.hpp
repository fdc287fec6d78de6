#pragma once
// hush::Error: the one exception type hush throws, in every layer. Its message says
// what went wrong and what to do about it; kind() lets code react without parsing
// text. Header-only: a layer that only throws (the tracer) links nothing for it.
#include <stdexcept>
#include <string>

namespace hush {

enum class ErrorKind {
    InvalidArgument,   // a file, setting, descriptor or call that is wrong whatever the machine
    NotFound,          // a named thing (file, shader, resource, tensor) is missing
    Unsupported,       // a format, usage, size or feature the machine lacks
    OutOfMemory,       // host or device memory exhausted
    Io,                // the file system refused (permissions, disk full, not a folder)
    // The GPU layer's kinds (rhi); named for what the user must do, not for the API.
    NoLoader,          // the GPU API's loader library could not be opened
    NoDriver,          // loader present, but no driver answers
    NoAdapter,         // no GPU, or none matches the request
    BindingMismatch,   // a bind group that does not match the pipeline's layout
    DeviceLost,        // the driver lost the device; recreate it
    Driver,            // any other failure the GPU driver reports
};

inline const char* toString(ErrorKind kind) {
    switch (kind) {
    case ErrorKind::InvalidArgument: return "invalid-argument";
    case ErrorKind::NotFound: return "not-found";
    case ErrorKind::Unsupported: return "unsupported";
    case ErrorKind::OutOfMemory: return "out-of-memory";
    case ErrorKind::Io: return "io";
    case ErrorKind::NoLoader: return "no-loader";
    case ErrorKind::NoDriver: return "no-driver";
    case ErrorKind::NoAdapter: return "no-adapter";
    case ErrorKind::BindingMismatch: return "binding-mismatch";
    case ErrorKind::DeviceLost: return "device-lost";
    case ErrorKind::Driver: return "driver";
    }
    return "unknown";
}

class Error : public std::runtime_error {
public:
    Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
    ErrorKind kind() const noexcept { return kind_; }

private:
    ErrorKind kind_;
};

} // namespace hush
