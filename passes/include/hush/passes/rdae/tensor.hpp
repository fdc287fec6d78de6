#pragma once
// A feature map of the recurrent denoising autoencoder (Chaitanya et al. 2017) as
// one graph texture: channels in blocks of 4 (one RGBA texel per pixel and block),
// the blocks side by side in a grid of tiles. Level k of the network is the padded
// output size divided by 2^k; the padded size is the output rounded up to a multiple
// of 2^levels, so that every 2x2 pooling divides evenly. Pixel p of channel c lives at
//   tile(c / 4) * levelSize + p, component c % 4,  tile(b) = (b % tilesX, b / tilesX)
// (shaders/rdae/tensor.glsl reads and writes it; docs/passes/rdae.md, "Layout").
#include <cstdint>

#include <hush/graph/graph_model.hpp>
#include <hush/graph/handles.hpp>

namespace hush::passes {

struct RdaeTensorLayout {
    uint32_t blocks = 1;   // ceil(channels / 4)
    uint32_t tilesX = 1;   // about square: a wide tensor stays within texture limits
    uint32_t tilesY = 1;
};

RdaeTensorLayout rdaeTensorLayout(uint32_t channels);

struct RdaeTensor {
    graph::TextureHandle texture;
    uint32_t channels = 0;
    uint32_t level = 0;   // 0: full (padded) resolution, k: divided by 2^k
    RdaeTensorLayout layout() const { return rdaeTensorLayout(channels); }
    bool valid() const { return texture.valid(); }
};

// How tensors of one network are stored and sized.
struct RdaeTensorFormat {
    uint32_t levels = 6;                                // poolings: sizes pad to 2^levels
    rhi::Format format = rhi::Format::RGBA16Float;      // storage; arithmetic is fp32
};

// The graph texture of a tensor with `channels` channels at `level`.
graph::TextureInfo rdaeTensorInfo(uint32_t channels, uint32_t level, const RdaeTensorFormat& format);
// One block's extent at `level` for a graph output of `output`.
rhi::Extent2D rdaeLevelSize(rhi::Extent2D output, uint32_t level, uint32_t levels);

} // namespace hush::passes
