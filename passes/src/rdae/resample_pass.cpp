#include "resample_pass.hpp"

#include "shader_variant.hpp"

namespace hush::passes::detail {

RdaeTensor addRdaeResamplePass(NodeContext& ctx, const std::string& name, const std::string& kernel,
                               const std::string& outputPort, const RdaeTensor& features, uint32_t outputLevel,
                               const RdaeTensorFormat& format) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get(rdaeShader(kernel, format));
    const auto layout = features.layout();
    rhi::PushConstants params(pipeline);
    params.set("tiles", layout.tilesX);
    const auto size = params.slot("size", rhi::ScalarType::Int32, 2);
    const uint32_t levels = format.levels, channels = features.channels;
    struct Out {
        graph::TextureHandle result;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& b, Out& o) {
        b.sample("features", features.texture);
        o.result = b.write(outputPort, b.create(name, rdaeTensorInfo(channels, outputLevel, format)));
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) mutable {
            const auto extent = rdaeLevelSize(pc.outputSize(), outputLevel, levels);
            const int32_t sizeValues[2] = {int32_t(extent.width), int32_t(extent.height)};
            params.set(size, std::span<const int32_t>(sizeValues));
            pc.dispatch(pipeline, group, extent, layout.blocks, params);
        };
    });
    return {out.result, channels, outputLevel};
}

} // namespace hush::passes::detail
