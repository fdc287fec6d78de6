// An integrator's smallest useful program: open Vulkan through hush, run one
// embedded compute shader (bench/copy_buffer) as a one-pass render graph over the
// application's buffers, and check what it wrote.
#include <cstdio>
#include <cstring>
#include <vector>

#include <hush/graph/render_graph.hpp>
#include <hush/rhi/rhi.hpp>
#include <hush/shaders/shaders.hpp>

using namespace hush::rhi;

int main() {
    try {
        Instance instance = Instance::create();
        Adapter adapter = instance.requestAdapter();
        Device device = adapter.createDevice({.label = "consumer"});
        std::printf("hush consumer: adapter %s, validation %s\n", adapter.info().name.c_str(),
                    instance.validationEnabled() ? "on" : "off");

        constexpr uint32_t count = 1000;   // vec4s; not a multiple of the workgroup size
        std::vector<float> input(count * 4);
        for (size_t i = 0; i < input.size(); ++i) {
            input[i] = float(i) * 0.5f - 100.0f;
        }
        const uint64_t bytes = input.size() * sizeof(float);
        const BufferUsage usage = BufferUsage::Storage | BufferUsage::CopySrc | BufferUsage::CopyDst;
        Buffer src = device.createBuffer({.label = "consumer.src", .size = bytes, .usage = usage});
        Buffer dst = device.createBuffer({.label = "consumer.dst", .size = bytes, .usage = usage});
        Queue queue = device.queue();
        queue.writeBuffer(src, 0, std::as_bytes(std::span(input)));

        ShaderModule module = device.createShaderModule(
            {.label = "bench/copy_buffer", .code = hush::shaders::find("bench/copy_buffer")});
        ComputePipeline pipeline = device.createComputePipeline({.label = "copy", .module = module});
        hush::graph::RenderGraph graph(device, {.label = "consumer"});
        auto in = graph.importBuffer("src", src, {.initialState = ResourceState::General,
                                                  .finalState = ResourceState::StorageRead});
        auto out = graph.importBuffer("dst", dst, {.initialState = ResourceState::Undefined,
                                                   .finalState = ResourceState::CopySrc});
        graph.addPass("copy", [&](hush::graph::PassBuilder& b) {
            auto read = b.read("src", in);
            auto written = b.write("dst", out);
            auto group = b.bindGroup(pipeline, 0, {{.binding = 0, .buffer = read}, {.binding = 1, .buffer = written}});
            return [=](hush::graph::PassContext& ctx) { ctx.dispatch(pipeline, group, {count, 1}, count); };
        });
        graph.execute();
        graph.waitIdle();

        std::vector<std::byte> raw = queue.readBuffer(dst);
        std::vector<float> output(raw.size() / sizeof(float));
        std::memcpy(output.data(), raw.data(), output.size() * sizeof(float));
        if (output != input) {
            std::fprintf(stderr, "hush consumer: FAIL: the copy differs from its source\n");
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
