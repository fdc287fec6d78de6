#include <hush/passes/bmfr/accumulate.hpp>

#include <cmath>

#include <hush/core/error.hpp>

namespace hush::passes {

namespace {
// Push constants of shaders/bmfr/accumulate.comp (same order).
struct AccumulateParams {
    float minWeight;
    float countCap;
    uint32_t historyValid;
    uint32_t pad = 0;
};
} // namespace

uint32_t bmfrAccumulateCountCap(const BmfrAccumulateSettings& settings) {
    const float w = settings.minWeight;
    if (!(std::isfinite(w) && w > 0.0f && w <= 1.0f))
        throw Error(ErrorKind::InvalidArgument,
                    "bmfr accumulate: minWeight must be in (0, 1], got " + std::to_string(w));
    if (settings.format != rhi::Format::RGBA32Float && settings.format != rhi::Format::RGBA16Float)
        throw Error(ErrorKind::InvalidArgument, "bmfr accumulate: format must be RGBA32Float or RGBA16Float");
    // In double, and with a little slack, so that 0.2f (0.200000003) gives 5, not 6.
    return uint32_t(std::ceil(1.0 / double(w) - 1e-5));
}

graph::TextureHandle addBmfrAccumulatePass(NodeContext& ctx, const std::string& name, graph::TextureHandle input,
                                           graph::TextureHandle reprojection, const BmfrAccumulateSettings& settings) {
    const uint32_t cap = bmfrAccumulateCountCap(settings);
    const bool half = settings.format == rhi::Format::RGBA16Float;
    // One shader per output format: the image's format qualifier must be literal.
    const rhi::ComputePipeline pipeline = ctx.pipelines.get(half ? "bmfr/accumulate_rgba16f" : "bmfr/accumulate");
    // The node's own output last frame: colour in rgb, sample count in alpha.
    const graph::TextureHandle history = ctx.graph.history(name, fullSize(settings.format));
    graph::TextureHandle out;
    ctx.graph.addPass(name, [&](graph::PassBuilder& b) {
        auto in = b.sample("current", input);
        auto decision = b.sample("reprojection", reprojection);
        auto prev = b.sample("history", history);
        out = b.write("accumulated", b.create(name, fullSize(settings.format)));
        auto group = b.bindGroup(pipeline, 0,
                                 {{.name = "current", .texture = in},
                                  {.name = "reprojection", .texture = decision},
                                  {.name = "history", .texture = prev},
                                  {.name = "accumulated", .texture = out}});
        const graph::TextureHandle target = out;
        const AccumulateParams base{settings.minWeight, float(cap), 0u};
        return [=](graph::PassContext& pc) {
            AccumulateParams params = base;
            params.historyValid = pc.historyValid() ? 1u : 0u;
            pc.dispatch(pipeline, group, pc.texture(target).size(), params);
        };
    });
    return out;
}

} // namespace hush::passes
