#include "parallel_rows.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace hush::tracer::detail {

void parallelRows(uint32_t rows, uint32_t threads, const std::function<void(uint32_t)>& rowFn) {
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    std::atomic<uint32_t> nextRow{0};
    std::exception_ptr failure;
    std::mutex failureMutex;
    std::vector<std::thread> pool;
    for (uint32_t t = 0; t < threads; ++t)
        pool.emplace_back([&] {
            try {
                for (uint32_t y = nextRow++; y < rows; y = nextRow++) rowFn(y);
            } catch (...) {
                std::lock_guard lock(failureMutex);
                if (!failure) failure = std::current_exception();
                nextRow = rows;   // stop the others
            }
        });
    for (auto& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
}

} // namespace hush::tracer::detail
