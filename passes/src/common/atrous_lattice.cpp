#include <hush/passes/common/atrous_lattice.hpp>

#include <algorithm>

namespace hush::passes {

namespace {
// Invocations along an axis of `extent` pixels. A step beyond the extent leaves one
// pixel of each block outside: at most `extent` invocations, each with one pixel.
uint32_t latticeThreads(uint32_t extent, uint32_t step, uint64_t block) {
    const uint64_t s = std::max<uint32_t>(step, 1);
    const uint64_t cells = (uint64_t(extent) + block * s - 1) / (block * s);
    return uint32_t(std::min<uint64_t>(cells * s, extent));
}
} // namespace

rhi::Extent2D atrousThreads(rhi::Extent2D size, uint32_t step, uint32_t block) {
    const uint64_t b = std::max<uint32_t>(block, 1);
    return {latticeThreads(size.width, step, b), latticeThreads(size.height, step, b)};
}

} // namespace hush::passes
