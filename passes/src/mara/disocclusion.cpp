#include <hush/passes/mara/disocclusion.hpp>

#include <cmath>

#include <hush/passes/settings_push_constants.hpp>

namespace hush::passes {

namespace {
// Pixels per invocation along the filtered axis: kRun in shaders/mara/window_min.glsl.
constexpr uint32_t kMaraWindowRun = 8;

uint32_t runs(uint32_t extent) {
    return (extent + kMaraWindowRun - 1) / kMaraWindowRun;
}
} // namespace

int maraDisocclusionBoxRadius(const MaraDisocclusionSettings& settings, uint32_t width) {
    return int(std::lround(double(settings.maxRadius) * double(width)));
}

graph::TextureHandle addMaraDisocclusionPass(NodeContext& ctx, const std::string& name, graph::TextureHandle temporal,
                                             const MaraDisocclusionSettings& settings) {
    const rhi::ComputePipeline horizontal = ctx.pipelines.get("mara/disocclusion_horizontal");
    const rhi::ComputePipeline vertical = ctx.pipelines.get("mara/disocclusion_vertical");
    rhi::PushConstants rowParams(horizontal);
    rhi::PushConstants columnParams(vertical);
    setFromSettings(columnParams, settings);
    const auto rowRadius = rowParams.slot("boxRadius", rhi::ScalarType::Int32);
    const auto columnRadius = columnParams.slot("boxRadius", rhi::ScalarType::Int32);
    const MaraDisocclusionSettings s = settings;
    struct Rows {
        graph::TextureHandle rowMin;
    };
    const auto rows = ctx.graph.addPass<Rows>(name + ".horizontal", [&](graph::PassBuilder& b, Rows& o) {
        b.sample("temporal", temporal);
        o.rowMin = b.write("row_min", b.create(name + ".row_min", fullSize(rhi::Format::R32Float)));
        const auto group = b.bindGroup(horizontal);
        return [=](graph::PassContext& pc) mutable {
            const auto size = pc.texture(o.rowMin).size();
            rowParams.set(rowRadius, int32_t(maraDisocclusionBoxRadius(s, size.width)));
            pc.dispatch(horizontal, group, {runs(size.width), size.height}, rowParams);
        };
    });
    struct Out {
        graph::TextureHandle radius;
    };
    const auto out = ctx.graph.addPass<Out>(name + ".vertical", [&](graph::PassBuilder& b, Out& o) {
        b.sample("row_min", rows.rowMin);
        b.sample("temporal", temporal);
        o.radius = b.write("radius", b.create(name, fullSize(rhi::Format::R32Float)));
        const auto group = b.bindGroup(vertical);
        return [=](graph::PassContext& pc) mutable {
            const auto size = pc.texture(o.radius).size();
            columnParams.set(columnRadius, int32_t(maraDisocclusionBoxRadius(s, size.width)));
            pc.dispatch(vertical, group, {size.width, runs(size.height)}, columnParams);
        };
    });
    return out.radius;
}

} // namespace hush::passes
