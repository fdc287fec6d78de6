#pragma once
// The C boundary: every hush* function body runs inside guarded(), which turns any
// exception into a status and the thread's last-error message, so that nothing
// throws into C and nothing aborts the host process.
#include <exception>
#include <new>
#include <string>

#include <hush/core/error.hpp>
#include <hush/hush.h>

namespace hush::capi {

void setLastError(const std::string& message);
void clearLastError();
HushStatus statusOf(ErrorKind kind);

// An argument the caller got wrong: hush::Error (InvalidArgument) naming it.
[[noreturn]] void badArgument(const char* argument, const std::string& why);
template <class T> T* required(T* pointer, const char* argument) {
    if (!pointer) badArgument(argument, "is NULL");
    return pointer;
}

template <class F> HushStatus guarded(const char* function, F&& body) {
    try {
        clearLastError();
        body();
        return HUSH_SUCCESS;
    } catch (const Error& e) {
        setLastError(std::string(function) + ": " + e.what());
        return statusOf(e.kind());
    } catch (const std::bad_alloc&) {
        setLastError(std::string(function) + ": out of host memory");
        return HUSH_ERROR_OUT_OF_MEMORY;
    } catch (const std::exception& e) {
        setLastError(std::string(function) + ": internal error: " + e.what());
        return HUSH_ERROR_INTERNAL;
    } catch (...) {
        setLastError(std::string(function) + ": internal error (unknown exception)");
        return HUSH_ERROR_INTERNAL;
    }
}

} // namespace hush::capi
