#include "graph_selfcheck.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <hush/graph/render_graph.hpp>
#include <hush/rhi/rhi.hpp>
#include <hush_cli_shaders.hpp>

namespace hush::cli {

using namespace hush::rhi;
using namespace hush::graph;

namespace {

constexpr uint32_t kWidth = 37, kHeight = 23;   // odd sizes: dispatches round up past the edge
constexpr uint32_t kFrames = 3;
constexpr char kUnusedPass[] = "selfcheck.unused";

float inputValue(uint32_t x, uint32_t y, uint32_t c) { return float(x) * 0.25f - float(y) * 0.5f + float(c); }

} // namespace

bool GraphSelfCheckResult::passed() const {
    return frames == kFrames && maxError <= tolerance && culled.size() == 1 && culled[0] == kUnusedPass &&
           compiles == 1;
}

GraphSelfCheckResult runGraphSelfCheck(const Device& device) {
    auto pipeline = [&](const char* name) {
        return device.createComputePipeline(
            {.label = name, .module = device.createShaderModule({.label = name, .code = hush::cli_shaders::find(name)})});
    };
    const auto affine = pipeline("selfcheck/affine");
    const auto accumulate = pipeline("selfcheck/accumulate");

    auto input = device.createTexture({.label = "selfcheck.input", .size = {kWidth, kHeight},
                                       .format = Format::RGBA32Float,
                                       .usage = TextureUsage::StorageBinding | TextureUsage::CopyDst});
    auto output = device.createTexture({.label = "selfcheck.output", .size = {kWidth, kHeight},
                                        .format = Format::RGBA32Float,
                                        .usage = TextureUsage::StorageBinding | TextureUsage::CopySrc});
    std::vector<float> in(size_t(kWidth) * kHeight * 4);
    for (uint32_t y = 0; y < kHeight; ++y)
        for (uint32_t x = 0; x < kWidth; ++x)
            for (uint32_t c = 0; c < 4; ++c) in[(size_t(y) * kWidth + x) * 4 + c] = inputValue(x, y, c);
    auto queue = device.queue();
    queue.writeTexture({.texture = input, .data = std::as_bytes(std::span(in)), .after = ResourceState::StorageRead});

    RenderGraph g(device, {.label = "selfcheck"});
    g.setOutputSize({kWidth, kHeight});
    const TextureInfo rgba32f{.format = Format::RGBA32Float};
    auto src = g.importTexture("input", input, {.initialState = ResourceState::StorageRead,
                                                .finalState = ResourceState::StorageRead});
    auto dst = g.importTexture("output", output, {.initialState = ResourceState::Undefined,
                                                  .finalState = ResourceState::CopySrc});
    struct Affine {
        float scale, bias;
    };
    // `to`: an existing texture to write, or none to create one named after the pass.
    auto affinePass = [&](const std::string& name, TextureHandle from, Affine a, TextureHandle to = {}) {
        PushConstants params(affine);
        params.set("scale", a.scale).set("bias", a.bias);
        struct Out {
            TextureHandle written;
        };
        return g.addPass<Out>(name, [&](PassBuilder& b, Out& o) {
                    b.read("src", from);
                    o.written = b.write("dst", to ? to : b.create(name + ".out", rgba32f));
                    const auto group = b.bindGroup(affine);
                    return [=](PassContext& ctx) { ctx.dispatch(affine, group, ctx.outputSize(), params); };
                })
            .written;
    };
    const auto t1 = affinePass("selfcheck.double", src, {2.0f, 1.0f});   // 2x + 1
    const auto t2 = affinePass("selfcheck.halve", t1, {0.5f, 0.0f});     // x + 0.5
    affinePass(kUnusedPass, t1, {3.0f, 0.0f});                           // nobody reads it: culled
    struct Accumulated {
        TextureHandle sum;
    };
    const TextureHandle acc = g.addPass<Accumulated>("selfcheck.accumulate", [&](PassBuilder& b, Accumulated& o) {
        b.read("current", t2);
        const auto sum = b.create("selfcheck.accumulated", rgba32f);
        b.read("history", g.history(sum));   // the sum of the frames so far
        o.sum = b.write("dst", sum);
        const auto group = b.bindGroup(accumulate);
        PushConstants params(accumulate);
        const auto historyValid = params.slot("historyValid", ScalarType::Uint32);
        return [=](PassContext& ctx) mutable {
            params.set(historyValid, uint32_t(ctx.historyValid()));
            ctx.dispatch(accumulate, group, ctx.outputSize(), params);
        };
    }).sum;
    affinePass("selfcheck.present", acc, {1.0f, 0.0f}, dst);

    GraphSelfCheckResult result;
    result.tolerance = 1e-4;
    for (uint32_t frame = 0; frame < kFrames; ++frame) {
        g.execute();
        g.waitIdle();
        const auto bytes = queue.readTexture({.texture = output, .state = ResourceState::CopySrc});
        std::vector<float> out(in.size());
        std::memcpy(out.data(), bytes.data(), out.size() * sizeof(float));
        for (size_t i = 0; i < in.size(); ++i) {
            const double expected = double(frame + 1) * (double(in[i]) + 0.5);   // the history sums the frames
            result.maxError = std::max(result.maxError, std::abs(double(out[i]) - expected));
        }
        ++result.frames;
    }
    result.culled = g.culledPasses();
    result.compiles = g.compileCount();
    result.timed = g.timings().valid;
    result.totalGpuMs = g.timings().totalGpuMs;
    result.dot = g.dumpDot();
    result.json = g.dumpJson();
    return result;
}

} // namespace hush::cli
