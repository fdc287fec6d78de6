// hush-bench-chains, speed: per-pass GPU time of a chain run over one uploaded frame,
// each pass's effective bandwidth against the roofline measured in the same run, and
// the chain's transient memory with and without aliasing.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <map>
#include <set>

#include <hush/graph/compile_steps.hpp>
#include <hush/passes/chain_file.hpp>
#include <hush/passes/rdae/chain.hpp>
#include <hush/core/error.hpp>
#include <hush/tracer/builtin_scenes.hpp>
#include <hush/tracer/renderer.hpp>

#include "bandwidth_probe.hpp"
#include "fma_probe.hpp"
#include "chain_bench.hpp"
#include "frame_upload.hpp"

namespace hush::bench::chain_bench {
namespace {

struct PassBytes {
    uint64_t read = 0, written = 0;
    bool listedTiles = false;   // dispatched indirectly (PassRow::listedTiles)
};

uint64_t resourceBytes(const graph::GraphModel& model, uint32_t resource) {
    const auto& r = model.resources[resource];
    if (r.kind == graph::ResourceKind::Buffer) return r.buffer.size;
    const Extent2D extent = r.texture.size.resolve(model.outputSize);
    return uint64_t(extent.width) * extent.height * rhi::formatInfo(r.texture.format).bytesPerPixel;
}

// By pass name, for the live passes: the bytes of every distinct resource a pass
// reads and of every distinct one it writes (a read-write access counts in both).
// This is the least a pass must move; a kernel that reads a neighbourhood fetches
// texels more than once, from caches when it is lucky.
std::map<std::string, PassBytes> bytesByPass(const graph::GraphModel& model) {
    const graph::CullResult culled = graph::cull(model);
    std::map<std::string, PassBytes> out;
    for (size_t p = 0; p < model.passes.size(); ++p) {
        if (!culled.passAlive[p]) continue;
        std::set<uint32_t> reads, writes;
        for (const auto& access : model.passes[p].accesses) {
            if (access.resource == graph::kNone) continue;   // an optional port left unconnected
            out[model.passes[p].name].listedTiles |= access.access == graph::Access::IndirectRead;
            if (graph::isRead(access.access)) reads.insert(access.resource);
            if (graph::isWrite(access.access)) writes.insert(access.resource);
        }
        PassBytes& bytes = out[model.passes[p].name];
        for (uint32_t r : reads) bytes.read += resourceBytes(model, r);
        for (uint32_t r : writes) bytes.written += resourceBytes(model, r);
    }
    return out;
}

// GB/s (1 GB = 1e9 bytes) of `bytes` moved in `ms`; 0 for a zero time.
double gigabytesPerSecond(uint64_t bytes, double ms) { return ms > 0.0 ? double(bytes) / (ms * 1e6) : 0.0; }

uint64_t countNonFinite(const std::vector<float>& values) {
    uint64_t n = 0;
    for (float v : values) n += std::isfinite(v) ? 0 : 1;
    return n;
}

// Counted multiply-adds by pass name: the rdae network's convolutions, 9 x inputs x
// outputs per pixel of their level (of the padded frame).
std::map<std::string, double> multiplyAddsByPass(const passes::Chain& chain, Extent2D size) {
    std::map<std::string, double> out;
    const auto* rdae = dynamic_cast<const passes::RdaeChain*>(&passes::unwrapChain(chain));
    if (!rdae) return out;
    const auto a = rdae->architecture();
    for (const auto& conv : a.convolutions()) {
        const auto level = passes::rdaeLevelSize(size, conv.level, a.levels);
        out[rdae->name() + "." + conv.name] =
            9.0 * (conv.inputA + conv.inputB) * conv.outputs * double(level.width) * level.height;
    }
    return out;
}

} // namespace

bool countsArithmetic(const std::string& chain) { return !multiplyAddsByPass(*passes::makeChain(chain), {64, 64}).empty(); }

ComputeRoofline measureComputeRoofline(const rhi::Device& device, uint32_t runs) {
    const FmaTimings t = runFmaProbe(device, 3, runs);
    ComputeRoofline r{.measured = true, .ms = summarize(t.ms), .timer = t.timer, .verified = t.verified};
    r.gflops = double(t.flops) / (r.ms.median * 1e6);
    return r;
}

std::vector<tracer::Channel> denoiserChannels() {
    // Every layer a chain may read (Mara's too; asking for them makes `direct` Mara's
    // low-noise direct light, for every chain alike). The reference is added per frame.
    std::vector<tracer::Channel> channels;
    for (const auto channel : tracer::kAllChannels)
        if (channel != tracer::Channel::Reference) channels.push_back(channel);
    return channels;
}

tracer::Frame renderTimingFrame(Extent2D size) {
    const tracer::Renderer renderer(tracer::makeBuiltinScene("cornell"));
    tracer::RenderSettings settings;
    settings.width = size.width;
    settings.height = size.height;
    settings.channels = denoiserChannels();
    return renderer.render(0, settings);
}

Roofline measureRoofline(const rhi::Device& device, Extent2D size, uint32_t runs) {
    const ProbeCase probe{"texture rgba32f", ProbeKind::Texture, rhi::Format::RGBA32Float, size, 16};
    const core::CpuTimes before = core::sampleCpuTimes();
    const ProbeTimings timings = runDeviceProbe(device, probe, 3, runs);
    Roofline roofline{.size = size, .ms = summarize(timings.ms), .timer = timings.timer,
                      .verified = timings.verified, .otherCpuShare = core::otherCpuShare(before, core::sampleCpuTimes())};
    roofline.gbps = gigabytesPerSecond(2 * probe.bytes(), roofline.ms.median);
    return roofline;
}

TimingResult measureChainTiming(const rhi::Device& device, const std::string& chain, const tracer::Frame& frame,
                                const Roofline& roofline, const ComputeRoofline& compute, const Options& options) {
    const Extent2D size{frame.width, frame.height};
    TimingResult result{.chain = passes::makeChain(chain)->name(), .size = size, .frames = options.frames};

    // Memory first, aliasing off: a runner that compiles and is dropped again.
    {
        const uint64_t before = device.allocatedBytes();
        passes::ChainRunner separate(device, passes::makeChain(chain), size,
                                     {.label = result.chain, .aliasing = false});
        result.deviceBytesUnaliased = device.allocatedBytes() - before;
        result.unaliased = separate.graph().memory();
    }
    const uint64_t before = device.allocatedBytes();
    passes::ChainRunner runner(device, passes::makeChain(chain), size);
    result.deviceBytesAliased = device.allocatedBytes() - before;
    result.aliased = runner.graph().memory();
    result.barriersPerFrame = runner.graph().barrierCount();
    frames::uploadFrame(runner, frame);

    // The same input every frame: the work of each pass does not depend on the
    // pixel values, and the histories are valid from the second frame on.
    std::map<std::string, std::vector<double>> passMs;
    std::vector<double> totalMs, recordMs;
    const core::CpuTimes cpuBefore = core::sampleCpuTimes();
    for (uint32_t f = 0; f < options.warmup + options.frames; ++f) {
        runner.run();
        const auto& t = runner.graph().timings();
        if (f < options.warmup) continue;
        if (!t.valid)
            throw Error(ErrorKind::Unsupported, "chain '" + result.chain + "': the graph reported no GPU timings "
                                                "(timestamps unsupported on this adapter?)");
        for (const auto& p : t.passes) passMs[p.name].push_back(p.gpuMs);
        totalMs.push_back(t.totalGpuMs);
        recordMs.push_back(t.cpuRecordMs);
    }
    result.otherCpuShare = core::otherCpuShare(cpuBefore, core::sampleCpuTimes());
    result.totalGpuMs = summarize(totalMs);
    result.cpuRecordMs = summarize(recordMs);
    result.nonFiniteOutput = countNonFinite(runner.readDisplay()) + countNonFinite(runner.readRadiance());

    const auto bytes = bytesByPass(runner.graph().model());
    const auto work = multiplyAddsByPass(runner.chain(), size);
    for (const auto& name : runner.graph().passOrder()) {
        const auto samples = passMs.find(name);
        if (samples == passMs.end())
            throw Error(ErrorKind::InvalidArgument,
                        "chain '" + result.chain + "': pass '" + name + "' has no timings");
        PassRow row{.name = name, .gpuMs = summarize(samples->second)};
        if (const auto it = bytes.find(name); it != bytes.end()) {
            row.bytesRead = it->second.read;
            row.bytesWritten = it->second.written;
            row.listedTiles = it->second.listedTiles;
        }
        if (!row.listedTiles) {
            row.gbps = gigabytesPerSecond(row.bytesRead + row.bytesWritten, row.gpuMs.median);
            row.ofRoofline = roofline.gbps > 0.0 ? row.gbps / roofline.gbps : 0.0;
        }
        if (const auto it = work.find(name); it != work.end()) {
            row.multiplyAdds = it->second;
            row.gflops = 2.0 * row.multiplyAdds / (row.gpuMs.median * 1e6);
            row.ofComputeRoofline = compute.gflops > 0.0 ? row.gflops / compute.gflops : 0.0;
            result.multiplyAdds += row.multiplyAdds;
        }
        result.sumOfPassMedians += row.gpuMs.median;
        if (!row.listedTiles) result.bytes += row.bytesRead + row.bytesWritten;
        result.passes.push_back(std::move(row));
    }
    result.gbps = gigabytesPerSecond(result.bytes, result.totalGpuMs.median);
    result.ofRoofline = roofline.gbps > 0.0 ? result.gbps / roofline.gbps : 0.0;
    result.multiplyAddsPerPixel = result.multiplyAdds / (double(size.width) * size.height);
    result.gflops = 2.0 * result.multiplyAdds / (result.totalGpuMs.median * 1e6);
    result.ofComputeRoofline = compute.gflops > 0.0 ? result.gflops / compute.gflops : 0.0;
    return result;
}

} // namespace hush::bench::chain_bench
