#include <hush/passes/eaw/atrous.hpp>

#include <cmath>

#include <hush/passes/common/atrous_lattice.hpp>

namespace hush::passes {

namespace {
// Pixels per axis per invocation: shaders/eaw/atrous.comp's HUSH_ATROUS_BLOCK
// (docs/passes/atrous-lattice.md: 4 measured fastest with 5; 2, 3, 6 and 8 slower).
constexpr uint32_t kLatticeBlock = 4;

// sigma^2, floored so that the shader's division is never 0/0 (see the header).
float guardedSquare(float sigma) {
    constexpr float kMinSigmaSquared = 1e-30f;
    const float squared = sigma * sigma;
    return squared > kMinSigmaSquared ? squared : kMinSigmaSquared;
}
} // namespace

uint32_t eawAtrousStep(uint32_t level) {
    constexpr uint32_t kMaxLevel = 16;
    return 1u << (level < kMaxLevel ? level : kMaxLevel);
}

float eawColorSigma(const EawSettings& s, uint32_t level) {
    return std::ldexp(s.sigmaRtRelative > 0.0f ? s.sigmaRtRelative : s.sigmaRt, -int(level < 200 ? level : 200));
}

graph::TextureHandle addEawAtrousPass(NodeContext& ctx, const std::string& name, graph::TextureHandle color,
                                      graph::TextureHandle normal, graph::TextureHandle position,
                                      graph::TextureHandle depth, uint32_t level, const EawSettings& s) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("eaw/atrous");
    // The weights' squared sigmas are derived per level, so no field maps onto them by name.
    const uint32_t step = eawAtrousStep(level);
    rhi::PushConstants params(pipeline);
    params.set("step", int32_t(step))
        .set("sigmaRt2", guardedSquare(eawColorSigma(s, level)))
        .set("sigmaN2", guardedSquare(s.sigmaN))
        .set("sigmaX2", guardedSquare(depth.valid() ? s.sigmaXRelative : s.sigmaX))
        .set("depthRelative", depth.valid())
        .set("colorRelative", s.sigmaRtRelative > 0.0f);
    struct Out {
        graph::TextureHandle filtered;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& b, Out& o) {
        b.sample("color", color);
        b.sample("normal", normal);
        b.sample("position", position);
        b.sample("depth", depth, {.optional = true});
        o.filtered = b.write("filtered", b.create(name, fullSize()));
        const auto group = b.bindGroup(pipeline);
        return [=](graph::PassContext& pc) {
            pc.dispatch(pipeline, group, atrousThreads(pc.texture(o.filtered).size(), step, kLatticeBlock), params);
        };
    });
    return out.filtered;
}

graph::TextureHandle addEawAtrousPass(NodeContext& ctx, const std::string& name, graph::TextureHandle color,
                                      graph::TextureHandle normal, graph::TextureHandle position, uint32_t level,
                                      const EawSettings& s) {
    return addEawAtrousPass(ctx, name, color, normal, position, {}, level, s);
}

graph::TextureHandle addEawAtrousLevels(NodeContext& ctx, const std::string& name, graph::TextureHandle color,
                                        graph::TextureHandle normal, graph::TextureHandle position,
                                        graph::TextureHandle depth, const EawSettings& s) {
    graph::TextureHandle current = color;
    for (uint32_t i = 0; i < s.iterations; ++i)
        current = addEawAtrousPass(ctx, name + ".level." + std::to_string(i), current, normal, position, depth, i, s);
    return current;
}

graph::TextureHandle addEawAtrousLevels(NodeContext& ctx, const std::string& name, graph::TextureHandle color,
                                        graph::TextureHandle normal, graph::TextureHandle position,
                                        const EawSettings& s) {
    return addEawAtrousLevels(ctx, name, color, normal, position, {}, s);
}

} // namespace hush::passes
