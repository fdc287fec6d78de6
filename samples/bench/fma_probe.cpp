#include "fma_probe.hpp"

#include <chrono>
#include <cmath>
#include <cstring>

#include <hush/rhi/push_constants.hpp>
#include <hush/rhi/rhi.hpp>
#include <hush_bench_shaders.hpp>

namespace hush::bench {
namespace {

using namespace hush::rhi;

constexpr uint32_t kInvocations = 64 * 1024;
constexpr uint32_t kAccumulators = 8;

// a_{n+1} = a_n / 2 + c from a_0: a_n = 2c + (a_0 - 2c) / 2^n.
float closedForm(float a0, float c, uint32_t n) { return 2.0f * c + (a0 - 2.0f * c) * std::ldexp(1.0f, -int(std::min(n, 60u))); }

bool verify(const std::vector<std::byte>& bytes, uint32_t iterations) {
    const float add[4] = {1.0f, 0.5f, 0.25f, 0.125f};
    float expected[4] = {};
    for (int lane = 0; lane < 4; ++lane)
        for (uint32_t k = 0; k < kAccumulators; ++k) expected[lane] += closedForm(float(k + 1), add[lane], iterations);
    std::vector<float> values(bytes.size() / sizeof(float));
    std::memcpy(values.data(), bytes.data(), values.size() * sizeof(float));
    for (size_t i = 0; i < values.size(); ++i)
        if (std::abs(values[i] - expected[i % 4]) > 1e-3f * std::abs(expected[i % 4])) return false;
    return true;
}

} // namespace

FmaTimings runFmaProbe(const Device& device, uint32_t warmup, uint32_t runs, double minMs) {
    ShaderModule module = device.createShaderModule({.label = "bench/fma", .code = hush::bench_shaders::find("bench/fma")});
    ComputePipeline pipeline = device.createComputePipeline({.label = "bench/fma", .module = module});
    Buffer result = device.createBuffer({.label = "fma.result", .size = uint64_t(kInvocations) * 16,
                                         .usage = BufferUsage::Storage | BufferUsage::CopySrc});
    BindGroup group = device.createBindGroup(
        {.label = "fma", .layout = pipeline.getBindGroupLayout(0), .entries = {{.binding = 0, .buffer = result}}});
    const bool timed = device.adapterInfo().limits.timestampsSupported;
    QuerySet timestamps = device.createQuerySet({.label = "fma", .count = 2});
    Queue queue = device.queue();
    PushConstants params(pipeline);
    params.set("scale", 0.5f);

    ResourceState state = ResourceState::Undefined;
    auto once = [&](uint32_t iterations) {
        params.set("iterations", iterations);
        CommandEncoder encoder = device.createCommandEncoder({.label = "fma"});
        const BufferBarrier write{result, state, ResourceState::StorageWrite};   // write after last run's write
        encoder.barrier({}, std::span(&write, 1));
        state = ResourceState::StorageWrite;
        if (timed) encoder.resetQuerySet(timestamps, 0, 2);
        ComputePassDesc desc{.label = "fma"};
        if (timed) desc.timestampWrites = {.querySet = timestamps, .beginIndex = 0, .endIndex = 1};
        ComputePassEncoder pass = encoder.beginComputePass(desc);
        pass.setPipeline(pipeline);
        pass.setBindGroup(0, group);
        pass.setPushConstants(params);
        pass.dispatchThreads(kInvocations);
        pass.end();
        const auto start = std::chrono::steady_clock::now();
        queue.wait(queue.submit(encoder.finish()));
        const double host = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        return timed ? timestamps.elapsedMs(0, 1) : host;
    };

    uint32_t iterations = 16;
    once(iterations);   // the first dispatch may include compiling the pipeline (lavapipe's JIT)
    while (once(iterations) < minMs && iterations < (1u << 24)) iterations *= 2;
    FmaTimings out;
    out.timer = timed ? "gpu-timestamps" : "host-submit-wait";
    out.flops = uint64_t(kInvocations) * iterations * kAccumulators * 4 * 2;
    for (uint32_t r = 0; r < warmup + runs; ++r) {
        const double ms = once(iterations);
        if (r >= warmup) out.ms.push_back(ms);
    }
    CommandEncoder encoder = device.createCommandEncoder({.label = "fma.read"});
    const BufferBarrier read{result, state, ResourceState::CopySrc};
    encoder.barrier({}, std::span(&read, 1));
    queue.wait(queue.submit(encoder.finish()));
    out.verified = verify(queue.readBuffer(result), iterations);
    return out;
}

} // namespace hush::bench
