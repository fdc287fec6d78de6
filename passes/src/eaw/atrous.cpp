#include <hush/passes/eaw/atrous.hpp>

#include <cmath>

namespace hush::passes {

namespace {
// Matches the push-constant block of shaders/eaw/atrous.comp.
struct EawParams {
    int32_t step;
    float sigmaRt2, sigmaN2, sigmaX2;
    uint32_t depthRelative;
};

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
    return std::ldexp(s.sigmaRt, -int(level < 200 ? level : 200));
}

graph::TextureHandle addEawAtrousPass(NodeContext& ctx, const std::string& name, graph::TextureHandle color,
                                      graph::TextureHandle normal, graph::TextureHandle position,
                                      graph::TextureHandle depth, uint32_t level, const EawSettings& s) {
    const rhi::ComputePipeline pipeline = ctx.pipelines.get("eaw/atrous");
    graph::TextureHandle result;
    ctx.graph.addPass(name, [&](graph::PassBuilder& b) {
        auto c = b.sample("color", color);
        auto n = b.sample("normal", normal);
        auto x = b.sample("position", position);
        // Without depth the shader never reads its binding: give it the position.
        auto z = depth.valid() ? b.sample("depth", depth) : x;
        auto out = b.write("filtered", b.create(name, fullSize()));
        auto group = b.bindGroup(pipeline, 0,
                                 {{.name = "color", .texture = c},
                                  {.name = "normal", .texture = n},
                                  {.name = "position", .texture = x},
                                  {.name = "filtered", .texture = out},
                                  {.name = "depth", .texture = z}});
        result = out;
        const EawParams params{int32_t(eawAtrousStep(level)), guardedSquare(eawColorSigma(s, level)),
                               guardedSquare(s.sigmaN), guardedSquare(depth.valid() ? s.sigmaXRelative : s.sigmaX),
                               depth.valid() ? 1u : 0u};
        return [=](graph::PassContext& pc) { pc.dispatch(pipeline, group, pc.texture(out).size(), params); };
    });
    return result;
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
