// The copy probes of hush-bench-bandwidth: resources, barriers, timing, checking.
#include "bandwidth_probe.hpp"

#include <chrono>
#include <cstring>
#include <functional>
#include <span>

#include <hush/rhi/rhi.hpp>
#include <hush_bench_shaders.hpp>

namespace hush::bench {
namespace {

using namespace hush::rhi;
using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Source contents: finite, normal values in [1, 2), so that nothing on the way
// through the shader (fp16 -> fp32 -> fp16, denormal flushing) can alter them and
// the copy can be checked byte for byte. channelBytes is 2 (fp16) or 4 (fp32).
std::vector<std::byte> makePattern(uint64_t bytes, uint32_t channelBytes) {
    std::vector<std::byte> data(bytes);
    uint32_t state = 0x9E3779B9u;
    for (uint64_t offset = 0; offset + channelBytes <= bytes; offset += channelBytes) {
        state = state * 1664525u + 1013904223u;   // an LCG: cheap and reproducible
        if (channelBytes == 2) {
            uint16_t half = uint16_t(0x3C00u | (state >> 22));        // exponent 0, random mantissa
            std::memcpy(data.data() + offset, &half, sizeof half);
        } else {
            uint32_t single = 0x3F800000u | (state >> 9);
            std::memcpy(data.data() + offset, &single, sizeof single);
        }
    }
    return data;
}

// Everything the timing loop needs to know about one device probe. The RHI tracks
// no state, so the probe states each transition: before the first run, between
// runs (the destination is written again: write-after-write) and after the last
// (the destination is copied out for checking).
struct DeviceProbe {
    ComputePipeline pipeline;
    BindGroup group;
    std::vector<TextureBarrier> firstTextures, betweenTextures, lastTextures;
    std::vector<BufferBarrier> firstBuffers, betweenBuffers, lastBuffers;
    uint32_t threadsX = 1;
    uint32_t threadsY = 1;
    bool pushCount = false;   // copy_buffer takes the element count as a push constant
    uint32_t count = 0;
    std::function<std::vector<std::byte>()> readBack;
};

ComputePipeline makePipeline(const Device& device, const char* shader) {
    ShaderModule module = device.createShaderModule({.label = shader, .code = hush::bench_shaders::find(shader)});
    return device.createComputePipeline({.label = shader, .module = module});
}

DeviceProbe textureProbe(const Device& device, const ProbeCase& probe, std::span<const std::byte> pattern) {
    const char* shader = nullptr;
    if (probe.format == Format::RGBA16Float) {
        shader = "bench/copy_rgba16f";
    } else if (probe.format == Format::RGBA32Float) {
        shader = "bench/copy_rgba32f";
    } else {
        throw Error(ErrorKind::InvalidArgument,
                    "bandwidth: no copy kernel for " + std::string(toString(probe.format)));
    }
    const TextureUsage usage = TextureUsage::StorageBinding | TextureUsage::CopySrc | TextureUsage::CopyDst;
    Texture src = device.createTexture(
        {.label = "bandwidth.src", .size = probe.size, .format = probe.format, .usage = usage});
    Texture dst = device.createTexture(
        {.label = "bandwidth.dst", .size = probe.size, .format = probe.format, .usage = usage});
    Queue queue = device.queue();
    queue.writeTexture({.texture = src,
                        .data = pattern,
                        .before = ResourceState::Undefined,
                        .after = ResourceState::StorageRead});

    DeviceProbe out;
    out.pipeline = makePipeline(device, shader);
    out.group = device.createBindGroup({.label = "bandwidth",
                                        .layout = out.pipeline.getBindGroupLayout(0),
                                        .entries = {{.binding = 0, .texture = src}, {.binding = 1, .texture = dst}}});
    out.firstTextures = {{dst, ResourceState::Undefined, ResourceState::StorageWrite}};
    out.betweenTextures = {{dst, ResourceState::StorageWrite, ResourceState::StorageWrite}};
    out.lastTextures = {{dst, ResourceState::StorageWrite, ResourceState::CopySrc}};
    out.threadsX = probe.size.width;
    out.threadsY = probe.size.height;
    out.readBack = [queue, dst]() mutable {
        return queue.readTexture({.texture = dst, .state = ResourceState::CopySrc});
    };
    return out;
}

DeviceProbe bufferProbe(const Device& device, const ProbeCase& probe, std::span<const std::byte> pattern) {
    const uint64_t bytes = probe.bytes();
    const uint64_t limit = device.adapterInfo().limits.maxStorageBufferBindingBytes;
    if (bytes > limit) {
        throw Error(ErrorKind::Unsupported, "bandwidth: a " + std::to_string(bytes) +
                                                "-byte storage buffer exceeds this adapter's "
                                                "maxStorageBufferBindingBytes (" + std::to_string(limit) + ")");
    }
    const BufferUsage usage = BufferUsage::Storage | BufferUsage::CopySrc | BufferUsage::CopyDst;
    Buffer src = device.createBuffer({.label = "bandwidth.src", .size = bytes, .usage = usage});
    Buffer dst = device.createBuffer({.label = "bandwidth.dst", .size = bytes, .usage = usage});
    Queue queue = device.queue();
    queue.writeBuffer(src, 0, pattern);

    DeviceProbe out;
    out.pipeline = makePipeline(device, "bench/copy_buffer");
    out.group = device.createBindGroup({.label = "bandwidth",
                                        .layout = out.pipeline.getBindGroupLayout(0),
                                        .entries = {{.binding = 0, .buffer = src}, {.binding = 1, .buffer = dst}}});
    out.firstBuffers = {{src, ResourceState::CopyDst, ResourceState::StorageRead},
                        {dst, ResourceState::Undefined, ResourceState::StorageWrite}};
    out.betweenBuffers = {{dst, ResourceState::StorageWrite, ResourceState::StorageWrite}};
    out.lastBuffers = {{dst, ResourceState::StorageWrite, ResourceState::CopySrc}};
    out.count = uint32_t(bytes / 16);   // one vec4 per invocation
    out.threadsX = out.count;
    out.pushCount = true;
    out.readBack = [queue, dst]() mutable { return queue.readBuffer(dst); };
    return out;
}

void recordBarriers(CommandEncoder& encoder, std::span<const TextureBarrier> textures,
                    std::span<const BufferBarrier> buffers) {
    if (!textures.empty() || !buffers.empty()) {
        encoder.barrier(textures, buffers);
    }
}

} // namespace

ProbeTimings runDeviceProbe(const Device& device, const ProbeCase& probe, uint32_t warmup, uint32_t runs) {
    const uint32_t channelBytes = probe.kind == ProbeKind::Texture && probe.format == Format::RGBA16Float ? 2 : 4;
    const std::vector<std::byte> pattern = makePattern(probe.bytes(), channelBytes);
    DeviceProbe setup = probe.kind == ProbeKind::Texture ? textureProbe(device, probe, pattern)
                                                         : bufferProbe(device, probe, pattern);

    // Timestamps time the pass alone; without them the host times submit + wait,
    // which also counts the submission overhead (the timer field says which).
    const bool timed = device.adapterInfo().limits.timestampsSupported;
    const uint32_t total = warmup + runs;
    QuerySet timestamps;
    if (timed) {
        timestamps = device.createQuerySet({.label = "bandwidth", .count = 2 * total});
    }
    ProbeTimings result;
    result.timer = timed ? "gpu-timestamps" : "host-submit-wait";

    // One submission per run, waited on: runs never overlap, so each is timed alone.
    Queue queue = device.queue();
    for (uint32_t run = 0; run < total; ++run) {
        CommandEncoder encoder = device.createCommandEncoder({.label = "bandwidth"});
        if (run == 0) {
            recordBarriers(encoder, setup.firstTextures, setup.firstBuffers);
            if (timed) {
                encoder.resetQuerySet(timestamps, 0, 2 * total);
            }
        } else {
            recordBarriers(encoder, setup.betweenTextures, setup.betweenBuffers);
        }
        ComputePassDesc passDesc{.label = probe.kernel};
        if (timed) {
            passDesc.timestampWrites = {.querySet = timestamps, .beginIndex = 2 * run, .endIndex = 2 * run + 1};
        }
        ComputePassEncoder pass = encoder.beginComputePass(passDesc);
        pass.setPipeline(setup.pipeline);
        pass.setBindGroup(0, setup.group);
        if (setup.pushCount) {
            pass.setParams(setup.count);
        }
        pass.dispatchThreads(setup.threadsX, setup.threadsY);
        pass.end();
        if (run + 1 == total) {
            recordBarriers(encoder, setup.lastTextures, setup.lastBuffers);
        }
        CommandBuffer commands = encoder.finish();
        Clock::time_point start = Clock::now();
        queue.wait(queue.submit(commands));
        double hostMs = millisecondsSince(start);
        if (run >= warmup) {
            result.ms.push_back(timed ? timestamps.elapsedMs(2 * run, 2 * run + 1) : hostMs);
        }
    }

    std::vector<std::byte> copied = setup.readBack();
    result.verified = copied.size() == pattern.size() &&
                      std::memcmp(copied.data(), pattern.data(), pattern.size()) == 0;
    return result;
}

ProbeTimings runHostProbe(const ProbeCase& probe, uint32_t warmup, uint32_t runs) {
    const std::vector<std::byte> src = makePattern(probe.bytes(), 4);
    std::vector<std::byte> dst(src.size());   // zero-filled: its pages are touched before timing
    ProbeTimings result;
    result.timer = "host-clock";
    for (uint32_t run = 0; run < warmup + runs; ++run) {
        Clock::time_point start = Clock::now();
        std::memcpy(dst.data(), src.data(), src.size());
        double ms = millisecondsSince(start);
        if (run >= warmup) {
            result.ms.push_back(ms);
        }
    }
    // Reading dst back also keeps the compiler from dropping the copies.
    result.verified = std::memcmp(dst.data(), src.data(), src.size()) == 0;
    return result;
}

} // namespace hush::bench
