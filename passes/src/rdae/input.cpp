#include <hush/passes/rdae/input.hpp>

#include <hush/core/error.hpp>

#include "shader_variant.hpp"

namespace hush::passes {

RdaeTensor addRdaeInputPass(NodeContext& ctx, const std::string& name, graph::TextureHandle illumination,
                            graph::TextureHandle normal, graph::TextureHandle depth, graph::TextureHandle roughness,
                            FrameCameraRef camera, const RdaeTensorFormat& format) {
    if (!camera) throw Error(ErrorKind::InvalidArgument, "node '" + name + "' needs the frame's camera (view-space normals)");
    const rhi::ComputePipeline pipeline = ctx.pipelines.get(detail::rdaeShader("input", format));
    rhi::PushConstants params(pipeline);
    params.set("tiles", rdaeTensorLayout(kRdaeInputChannels).tilesX);
    const auto viewRow0 = params.slot("viewRow0", rhi::ScalarType::Float32, 4);
    const auto viewRow1 = params.slot("viewRow1", rhi::ScalarType::Float32, 4);
    const auto size = params.slot("size", rhi::ScalarType::Int32, 2);
    const auto image = params.slot("image", rhi::ScalarType::Int32, 2);
    const auto metresPerUnit = params.slot("metresPerUnit", rhi::ScalarType::Float32);
    const RdaeTensor tensor{.channels = kRdaeInputChannels, .level = 0};
    struct Out {
        graph::TextureHandle features;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& b, Out& o) {
        b.sample("illumination", illumination);
        b.sample("normal", normal);
        b.sample("depth", depth);
        b.sample("roughness", roughness);
        o.features = b.write("features", b.create(name, rdaeTensorInfo(tensor.channels, 0, format)));
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) mutable {
            const auto& v = camera->view;   // column-major: row r is v[r], v[4 + r], v[8 + r]
            const float row0[4] = {v[0], v[4], v[8], 0.0f}, row1[4] = {v[1], v[5], v[9], 0.0f};
            params.set(viewRow0, row0);
            params.set(viewRow1, row1);
            const auto level = rdaeLevelSize(pc.outputSize(), 0, format.levels);
            const auto frame = pc.outputSize();
            const int32_t sizeValues[2] = {int32_t(level.width), int32_t(level.height)};
            const int32_t imageValues[2] = {int32_t(frame.width), int32_t(frame.height)};
            params.set(size, std::span<const int32_t>(sizeValues));
            params.set(image, std::span<const int32_t>(imageValues));
            params.set(metresPerUnit, camera->metresPerUnit);
            pc.dispatch(pipeline, group, level, params);
        };
    });
    return {out.features, tensor.channels, 0};
}

} // namespace hush::passes
