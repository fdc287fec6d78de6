// An integrator's smallest useful program: open Vulkan through hush, compose a graph
// of its own from one of hush's denoising nodes (the tonemap node) over the
// application's textures, and check what it wrote against hush's CPU formula.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include <hush/passes/common/tonemap.hpp>
#include <hush/rhi/rhi.hpp>

using namespace hush::rhi;

int main() {
    try {
        Instance instance = Instance::create();
        Adapter adapter = instance.requestAdapter();
        Device device = adapter.createDevice({.label = "consumer"});
        std::printf("hush consumer: adapter %s, validation %s\n", adapter.info().name.c_str(),
                    instance.validationEnabled() ? "on" : "off");

        constexpr uint32_t width = 37, height = 11;   // not a multiple of the workgroup size
        std::vector<float> radiance(size_t(width) * height * 4);
        for (size_t i = 0; i < radiance.size(); ++i) radiance[i] = float(i % 97) * 0.05f;
        Texture in = device.createTexture({.label = "consumer.radiance", .size = {width, height},
                                           .format = Format::RGBA32Float,
                                           .usage = TextureUsage::TextureBinding | TextureUsage::CopyDst});
        Queue queue = device.queue();
        queue.writeTexture({.texture = in, .data = std::as_bytes(std::span(radiance)),
                            .after = ResourceState::SampledRead});

        hush::graph::RenderGraph graph(device, {.label = "consumer"});
        hush::passes::PipelineCache pipelines(device);
        hush::passes::NodeContext ctx{graph, pipelines};
        graph.setOutputSize({width, height});
        const auto source = graph.importTexture("radiance", in);
        const auto display = hush::passes::addTonemapPass(ctx, "tonemap", source);
        graph.markOutput(display);
        graph.execute();
        graph.waitIdle();

        const auto raw = queue.readTexture({.texture = graph.outputTexture(display), .state = graph.outputState(display)});
        std::vector<float> output(raw.size() / sizeof(float));
        std::memcpy(output.data(), raw.data(), output.size() * sizeof(float));
        double worst = 0.0;
        for (size_t p = 0; p < size_t(width) * height; ++p) {
            float expected[3] = {radiance[p * 4], radiance[p * 4 + 1], radiance[p * 4 + 2]};
            hush::passes::tonemap({}, expected);
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::fabs(double(output[p * 4 + c]) - expected[c]));
        }
        if (!(worst <= 1e-5)) {
            std::fprintf(stderr, "hush consumer: FAIL: the tonemap node differs from the CPU by %g\n", worst);
            return 1;
        }
        if (instance.validationMessageCount() != 0) {
            std::fprintf(stderr, "hush consumer: FAIL: %zu validation messages\n", instance.validationMessageCount());
            return 1;
        }
        std::printf("hush consumer: PASS\n");
        return 0;
    } catch (const hush::Error& error) {
        std::fprintf(stderr, "hush consumer: error (%s): %s\n", hush::toString(error.kind()), error.what());
        return 2;
    }
}
