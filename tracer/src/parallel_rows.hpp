#pragma once
// Rows of an image shared out to threads through an atomic counter: the renderer's
// and the ray-casting probe's one thread pool.
#include <cstdint>
#include <functional>

namespace hush::tracer::detail {

// Calls rowFn(y) once for every y in [0, rows) on `threads` threads (0: every core).
// The first exception stops the other threads from taking new rows and is rethrown.
void parallelRows(uint32_t rows, uint32_t threads, const std::function<void(uint32_t)>& rowFn);

} // namespace hush::tracer::detail
