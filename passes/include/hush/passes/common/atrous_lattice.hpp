#pragma once
// How a 5x5 a-trous level is dispatched on the a-trous lattice (shaders/common/
// atrous_lattice.glsl): one invocation per block of pixels spaced `step` apart,
// whose taps overlap, so that each texel is read fewer times.
//
// Used by eaw.atrous and svgf.atrous (4x4 blocks both): docs/passes/atrous-lattice.md.
#include <cstdint>

#include <hush/rhi/format.hpp>

namespace hush::passes {

// The invocations a level at `step` dispatches over `size` pixels: per axis, `step`
// invocations for every cell of block * step pixels (the last cell rounded up).
// `block`: the shader's HUSH_ATROUS_BLOCK (1 .. 8).
rhi::Extent2D atrousThreads(rhi::Extent2D size, uint32_t step, uint32_t block);

} // namespace hush::passes
