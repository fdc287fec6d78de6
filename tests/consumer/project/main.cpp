// An integrator's smallest useful program: open Vulkan through hush, run one
// embedded compute shader (bench/copy_buffer) and check what it wrote.
#include <cstdio>
#include <cstring>
#include <vector>

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
        BindGroup group = device.createBindGroup({.label = "copy",
                                                  .layout = pipeline.getBindGroupLayout(0),
                                                  .entries = {{.binding = 0, .buffer = src},
                                                              {.binding = 1, .buffer = dst}}});

        CommandEncoder encoder = device.createCommandEncoder();
        encoder.bufferBarrier({{src, ResourceState::CopyDst, ResourceState::StorageRead},
                               {dst, ResourceState::Undefined, ResourceState::StorageWrite}});
        ComputePassEncoder pass = encoder.beginComputePass({.label = "copy"});
        pass.setPipeline(pipeline);
        pass.setBindGroup(0, group);
        pass.setParams(count);
        pass.dispatchThreads(count);
        pass.end();
        encoder.bufferBarrier({{dst, ResourceState::StorageWrite, ResourceState::CopySrc}});
        queue.wait(queue.submit(encoder.finish()));

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
