#include <hush/passes/rdae/tensor.hpp>

#include <cmath>

namespace hush::passes {

RdaeTensorLayout rdaeTensorLayout(uint32_t channels) {
    RdaeTensorLayout l;
    l.blocks = std::max(1u, (channels + 3) / 4);
    l.tilesX = uint32_t(std::ceil(std::sqrt(double(l.blocks))));
    l.tilesY = (l.blocks + l.tilesX - 1) / l.tilesX;
    return l;
}

graph::TextureInfo rdaeTensorInfo(uint32_t channels, uint32_t level, const RdaeTensorFormat& format) {
    const auto l = rdaeTensorLayout(channels);
    return {.format = format.format,
            .size = graph::SizeSpec::tiled(1.0f / float(1u << level), 1u << format.levels, l.tilesX, l.tilesY)};
}

rhi::Extent2D rdaeLevelSize(rhi::Extent2D output, uint32_t level, uint32_t levels) {
    const uint32_t multiple = 1u << levels;
    auto side = [&](uint32_t v) { return (v + multiple - 1) / multiple * multiple >> level; };
    return {side(output.width), side(output.height)};
}

} // namespace hush::passes
