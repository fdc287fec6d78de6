// hush-bench-graph: what the render graph costs on top of the work it schedules.
//   (a) compile time of synthetic 100- and 1000-pass graphs (16x16 textures);
//   (b) per-frame CPU overhead of executing a compiled 20-pass chain at 1280x720 (and
//       at 16x16, where the GPU work is negligible), against the same dispatches,
//       timestamps and barriers recorded by hand with the rhi into a reusable encoder;
//   (c) transient memory of that chain with and without aliasing.
// Prints a table and writes bench-results/graph.json.
#include <array>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <thread>
#include <tuple>
#include <vector>

#include <hush/graph/compile_steps.hpp>
#include <hush/graph/render_graph.hpp>
#include <hush/rhi/rhi.hpp>
#include <hush_bench_shaders.hpp>

#include "bench_report.hpp"
#include "graph_bench.hpp"

namespace hush::bench {
namespace {

using namespace graph_bench;

using namespace hush::rhi;
using namespace hush::graph;
using Clock = std::chrono::steady_clock;

constexpr std::string_view kUsage =
    "usage: hush-bench-graph [--compiles N] [--frames N] [--warmup N] [--output PATH] [--adapter TEXT]\n"
    "\n"
    "Measures the render graph's own costs:\n"
    "  compile   declaring, planning (validate .. barriers, no GPU objects) and compile()\n"
    "            of synthetic chains of 100 and 1000 passes over 16x16 textures, each pass\n"
    "            reading the previous result and one further back;\n"
    "  overhead  CPU time per frame of RenderGraph::execute() for a 20-pass chain of copies\n"
    "            at 1280x720 RGBA16F (and at 16x16, where the GPU work is negligible),\n"
    "            against the same dispatches, timestamps and barriers\n"
    "            recorded by hand into a reusable rhi::CommandEncoder (trackLifetimes off),\n"
    "            frames interleaved (taking turns to go first), each started with the\n"
    "            device idle;\n"
    "  memory    transient bytes of that chain with and without aliasing.\n"
    "Reports medians (and min / max) of the runs.\n"
    "\n"
    "options:\n"
    "  --compiles N    timed compiles per synthetic graph (default 11)\n"
    "  --frames N      timed frames per variant at 1280x720, ten times that at 16x16 (default 60)\n"
    "  --warmup N      untimed frames first, likewise (default 5)\n"
    "  --output PATH   JSON results (default bench-results/graph.json)\n"
    "  --adapter TEXT  use the first adapter whose name contains TEXT (default: HUSH_ADAPTER)\n";


bool parseOptions(int argc, char** argv, Options& options) {
    for (int i = 1; i < argc; ++i) {
        std::string_view arg = argv[i];
        if (arg == "--help" || arg == "-h") return false;
        auto value = [&]() -> std::string_view {
            if (i + 1 >= argc) throw Error(ErrorKind::InvalidArgument, std::string(arg) + " needs a value");
            return argv[++i];
        };
        if (arg == "--compiles") {
            options.compiles = core::parseCount(value(), arg, 1);
        } else if (arg == "--frames") {
            options.frames = core::parseCount(value(), arg, 1);
        } else if (arg == "--warmup") {
            options.warmup = core::parseCount(value(), arg, 0);
        } else if (arg == "--output") {
            options.output = value();
        } else if (arg == "--adapter") {
            options.adapter.nameContains = value();
            options.adapter.nameFromEnvironment = false;
        } else {
            throw Error(ErrorKind::InvalidArgument,
                        "unknown argument '" + std::string(arg) + "' (see hush-bench-graph --help)");
        }
    }
    return true;
}

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}


// Halfs in [1, 2): exact through any number of copies.
std::vector<uint16_t> inputTexels(Extent2D size) {
    std::vector<uint16_t> texels(size_t(size.width) * size.height * 4);
    for (size_t i = 0; i < texels.size(); ++i) texels[i] = uint16_t(0x3C00u + (i * 7919u) % 1024u);
    return texels;
}

// An RGBA16F texture the application owns, holding inputTexels, left in StorageRead.
Texture makeInput(const Device& device, Extent2D size) {
    auto texture = device.createTexture({.label = "input",
                                         .size = size,
                                         .format = Format::RGBA16Float,
                                         .usage = TextureUsage::StorageBinding | TextureUsage::CopyDst});
    const auto texels = inputTexels(size);
    device.queue().writeTexture(
        {.texture = texture, .data = std::as_bytes(std::span(texels)), .after = ResourceState::StorageRead});
    return texture;
}

// A chain of `passes` copies: t0 = copy(input), t_i = copy(t_{i-1}). With skipReads
// (and the copy_skip shader), pass i also reads t_{i/2} as "skip": it shapes lifetimes
// and barriers as a pass reading two earlier results would. The last result is the
// graph's output.
TextureHandle declareChain(RenderGraph& g, const ComputePipeline& copy, TextureHandle input, uint32_t passes,
                           Extent2D size, bool skipReads) {
    std::vector<TextureHandle> results;
    results.reserve(passes);
    for (uint32_t i = 0; i < passes; ++i) {
        g.addPass("copy." + std::to_string(i), [&](PassBuilder& b) {
            b.read("src", i == 0 ? input : results[i - 1]);
            if (skipReads) b.read("skip", i >= 2 ? results[i / 2] : TextureHandle{}, {.optional = true});
            const auto dst = b.write(
                "dst", b.create("t" + std::to_string(i),
                                {.format = Format::RGBA16Float, .size = SizeSpec::absolute(size.width, size.height)}));
            const auto group = b.bindGroup(copy);
            results.push_back(dst);
            return [&copy, group, size](PassContext& ctx) { ctx.dispatch(copy, group, size); };
        });
    }
    g.markOutput(results.back());
    return results.back();
}

// (a) ---------------------------------------------------------------------------


CompileRow benchCompile(const Device& device, const ComputePipeline& copy, uint32_t passes, uint32_t runs) {
    constexpr Extent2D kSize{16, 16};
    const auto input = makeInput(device, kSize);
    std::vector<double> declare, plan, compile;
    std::array<std::vector<double>, kStepCount> steps;
    CompileRow row{.passes = passes};
    for (uint32_t run = 0; run <= runs; ++run) {   // run 0 warms caches and is not counted
        auto start = Clock::now();
        RenderGraph g(device, {.label = "synthetic"});
        const auto in = g.importTexture(
            "input", input, {.initialState = ResourceState::StorageRead, .finalState = ResourceState::StorageRead});
        declareChain(g, copy, in, passes, kSize, true);
        const double declareMs = msSince(start);

        // The planning steps alone, on the declared model: no GPU objects. Aliasing is
        // planned for items of the textures' size; glue between the steps is not timed.
        std::array<double, kStepCount> stepMs{};
        auto timed = [&](size_t step, auto&& f) {
            const auto t0 = Clock::now();
            f();
            stepMs[step] = msSince(t0);
        };
        const auto& m = g.model();
        CullResult c;
        std::vector<uint32_t> o;
        std::vector<Lifetime> life;
        AliasPlan aliasPlan;
        BarrierPlan barrierPlan;
        timed(0, [&] { validate(m); });
        timed(1, [&] { c = cull(m); });
        timed(2, [&] { o = order(m, c); });
        timed(3, [&] { life = lifetimes(m, o); });
        std::vector<AliasItem> items;
        std::vector<uint32_t> itemResource;
        for (uint32_t r = 0; r < m.resources.size(); ++r)
            if (m.resources[r].origin == ResourceOrigin::Transient && !m.resources[r].output && life[r].used()) {
                items.push_back({uint64_t(kSize.width) * kSize.height * 8, 256, life[r]});
                itemResource.push_back(r);
            }
        timed(4, [&] { aliasPlan = planAliasing(items); });
        std::map<uint64_t, uint32_t> atOffset;   // equal sizes: sharing memory means sharing an offset
        for (const uint64_t offset : aliasPlan.offsets) ++atOffset[offset];
        std::vector<bool> aliased(m.resources.size(), false);
        for (size_t i = 0; i < items.size(); ++i) aliased[itemResource[i]] = atOffset[aliasPlan.offsets[i]] > 1;
        timed(5, [&] { barrierPlan = planBarriers(m, o, aliased); });

        start = Clock::now();
        g.compile();
        const double compileMs = msSince(start);
        if (run == 0) {
            row.barriers = g.barrierCount();
            row.memory = g.memory();
            g.execute();   // the synthetic graph runs, too
            g.waitIdle();
            if (barrierPlan.count() != g.barrierCount())
                std::fprintf(stderr, "hush-bench-graph: planned %zu barriers alone, %zu in compile()\n",
                             barrierPlan.count(), g.barrierCount());
            continue;
        }
        declare.push_back(declareMs);
        double planTotal = 0.0;
        for (size_t i = 0; i < kStepCount; ++i) {
            steps[i].push_back(stepMs[i]);
            planTotal += stepMs[i];
        }
        plan.push_back(planTotal);
        compile.push_back(compileMs);
    }
    row.declareMs = summarize(declare);
    row.planMs = summarize(plan);
    row.compileMs = summarize(compile);
    for (size_t i = 0; i < kStepCount; ++i) row.stepMs[i] = summarize(steps[i]);
    return row;
}

// (b) and (c) ---------------------------------------------------------------------


// The chain recorded by hand: its own textures, bind groups, timestamps, and the
// barriers the graph planned for the same chain (RHI lists made once, like the graph's).
class HandChain {
public:
    HandChain(const Device& device, const ComputePipeline& copy, const Texture& input, const RenderGraph& graph,
              Extent2D size)
        : device_(device), copy_(copy), size_(size) {
        const auto& m = graph.model();
        const auto o = order(m, cull(m));
        passes_ = uint32_t(o.size());
        textures_.resize(m.resources.size());
        for (uint32_t r = 0; r < m.resources.size(); ++r) {
            if (m.resources[r].origin == ResourceOrigin::Imported) {
                textures_[r] = input;
                continue;
            }
            textures_[r] =
                device.createTexture({.label = "hand." + m.resources[r].name,
                                      .size = size,
                                      .format = Format::RGBA16Float,
                                      .usage = TextureUsage::StorageBinding |
                                               (m.resources[r].output ? TextureUsage::CopySrc : TextureUsage::None)});
        }
        // Pass i reads resource i (input, t0, ...) and writes resource i + 1.
        for (uint32_t i = 0; i < passes_; ++i)
            groups_.push_back(device.createBindGroup(
                {.label = "hand.copy." + std::to_string(i),
                 .layout = copy.getBindGroupLayout(0),
                 .entries = {{.name = "src", .texture = textures_[i]}, {.name = "dst", .texture = textures_[i + 1]}}}));
        const auto plan = planBarriers(m, o, std::vector<bool>(m.resources.size(), false));
        auto convert = [&](const std::vector<PlannedBarrier>& planned) {
            std::vector<TextureBarrier> out;
            for (const auto& b : planned) out.push_back({textures_[b.resource], b.before, b.after, b.discard});
            return out;
        };
        for (const auto& list : plan.beforePass) beforePass_.push_back(convert(list));
        frameEnd_ = convert(plan.frameEnd);
        barrierCount_ = plan.count();
        encoder_ = device.createCommandEncoder({.label = "hand", .reusable = true, .trackLifetimes = false});
        encoder_.finish();
        queries_ = device.createQuerySet({.label = "hand.timestamps", .count = 2 * passes_ + 2});
        ticks_.assign(2 * passes_ + 2, 0);
    }

    // Records and submits one frame; returns {record ms, wait + record + submit ms} and
    // then waits for the frame. Like RenderGraph::execute(), it first waits for the
    // encoder's last submission (complete by then) before reusing the encoder.
    std::pair<double, double> frame() {
        auto queue = device_.queue();
        const auto start = Clock::now();
        if (last_) queue.wait(last_);
        const auto recordStart = Clock::now();
        encoder_.reset();
        encoder_.writeTimestamp(queries_, 0);
        for (uint32_t i = 0; i < passes_; ++i) {
            if (!beforePass_[i].empty()) encoder_.barrier(beforePass_[i]);
            encoder_.writeTimestamp(queries_, 1 + 2 * i);
            auto pass = encoder_.beginComputePass();
            pass.setPipeline(copy_);
            pass.setBindGroup(0, groups_[i]);
            pass.dispatchThreads(size_.width, size_.height);
            pass.end();
            encoder_.writeTimestamp(queries_, 2 + 2 * i);
        }
        if (!frameEnd_.empty()) encoder_.barrier(frameEnd_);
        encoder_.writeTimestamp(queries_, 1 + 2 * passes_);
        const auto commands = encoder_.finish();
        const double recordMs = msSince(recordStart);
        last_ = queue.submit(commands);
        const double totalMs = msSince(start);
        queue.wait(last_);
        queries_.readTicks(0, ticks_);
        return {recordMs, totalMs};
    }

    size_t barrierCount() const { return barrierCount_; }
    const Texture& output() const { return textures_.back(); }

private:
    Device device_;
    ComputePipeline copy_;
    Extent2D size_;
    uint32_t passes_ = 0;
    std::vector<Texture> textures_;
    std::vector<BindGroup> groups_;
    std::vector<std::vector<TextureBarrier>> beforePass_;
    std::vector<TextureBarrier> frameEnd_;
    size_t barrierCount_ = 0;
    CommandEncoder encoder_;
    QuerySet queries_;
    std::vector<uint64_t> ticks_;
    SubmissionId last_ = 0;
};

MemoryRow benchMemory(const Device& device, const ComputePipeline& copy, uint32_t passes, Extent2D size) {
    const auto input = makeInput(device, size);
    MemoryRow row;
    row.chain = "copy chain, " + std::to_string(passes) + " passes, " + std::to_string(size.width) + "x" +
                std::to_string(size.height) + " rgba16float";
    for (const bool aliasing : {true, false}) {
        RenderGraph g(device, {.label = "memory", .aliasing = aliasing});
        declareChain(
            g, copy,
            g.importTexture("input", input,
                            {.initialState = ResourceState::StorageRead, .finalState = ResourceState::StorageRead}),
            passes, size, false);
        const uint64_t before = device.allocatedBytes();
        g.compile();
        const uint64_t allocated = device.allocatedBytes() - before;
        (aliasing ? row.aliased : row.separate) = g.memory();
        (aliasing ? row.deviceBytesAliased : row.deviceBytesSeparate) = allocated;
    }
    return row;
}

OverheadResult benchOverhead(const Device& device, const ComputePipeline& copy, uint32_t warmup, uint32_t frames,
                             uint32_t passes, Extent2D size) {
    OverheadResult result{.passes = passes, .frames = frames, .size = size};
    const auto input = makeInput(device, size);
    const ImportDesc importDesc{.initialState = ResourceState::StorageRead, .finalState = ResourceState::StorageRead};

    // (b) Without aliasing, so that graph and hand-recorded chain have the same textures
    // and the same barriers (no aliasing memory barriers in the graph's lists).
    RenderGraph g(device, {.label = "overhead", .framesInFlight = 2, .aliasing = false});
    const auto out = declareChain(g, copy, g.importTexture("input", input, importDesc), passes, size, false);
    g.compile();
    HandChain hand(device, copy, input, g, size);
    result.barriersPerFrame = g.barrierCount();
    if (hand.barrierCount() != g.barrierCount())
        throw Error(ErrorKind::InvalidArgument, "the hand-recorded chain has " + std::to_string(hand.barrierCount()) +
                                                    " barriers, the graph " + std::to_string(g.barrierCount()));

    std::vector<double> graphExecute, graphRecord, handExecute, handRecord, gpu;
    for (uint32_t f = 0; f < warmup + frames; ++f) {
        // The graph: execute() with the device idle, then wait (not timed). The two
        // take turns going first, so that neither always follows the other's wait.
        double executeMs = 0.0, recordMs = 0.0, totalMs = 0.0;
        auto graphFrame = [&] {
            const auto start = Clock::now();
            g.execute();
            executeMs = msSince(start);
            g.waitIdle();
        };
        auto handFrame = [&] { std::tie(recordMs, totalMs) = hand.frame(); };
        if (f % 2) {
            handFrame();
            graphFrame();
        } else {
            graphFrame();
            handFrame();
        }
        if (f < warmup) continue;
        graphExecute.push_back(executeMs);
        graphRecord.push_back(g.timings().cpuRecordMs);
        gpu.push_back(g.timings().totalGpuMs);
        handRecord.push_back(recordMs);
        handExecute.push_back(totalMs);
    }
    result.graphExecuteMs = summarize(graphExecute);
    result.graphRecordMs = summarize(graphRecord);
    result.handExecuteMs = summarize(handExecute);
    result.handRecordMs = summarize(handRecord);
    result.gpuMs = summarize(gpu);
    result.executeRatio = result.graphExecuteMs.median / result.handExecuteMs.median;
    result.recordRatio = result.graphRecordMs.median / result.handRecordMs.median;

    // Both made the same image: the input, copied `passes` times.
    auto queue = device.queue();
    const auto fromGraph = queue.readTexture({.texture = g.outputTexture(out), .state = g.outputState(out)});
    const auto fromHand = queue.readTexture({.texture = hand.output(), .state = ResourceState::StorageWrite});
    const auto texels = inputTexels(size);
    const auto expected = std::as_bytes(std::span(texels));
    result.verified = fromGraph.size() == expected.size() && fromHand.size() == expected.size() &&
                      std::memcmp(fromGraph.data(), expected.data(), expected.size()) == 0 &&
                      std::memcmp(fromHand.data(), expected.data(), expected.size()) == 0;
    return result;
}

// Output ----------------------------------------------------------------------------

int run(const Options& options) {
    Instance instance = Instance::create();
    Adapter adapter = instance.requestAdapter(options.adapter);
    const AdapterInfo& info = adapter.info();
    std::printf("[graph] adapter: %s (%s, %s)\n", info.name.c_str(), info.driverName.c_str(), info.driverInfo.c_str());
    std::printf("[graph] %u compiles per graph, %u warm-up + %u timed frames, validation %s\n", options.compiles,
                options.warmup, options.frames,
                instance.validationEnabled() ? "on (slower: figures not representative)" : "off");
    Device device = adapter.createDevice({.label = "hush-bench-graph"});
    auto pipeline = [&](const char* name) {
        return device.createComputePipeline(
            {.label = name, .module = device.createShaderModule({.label = name, .code = bench_shaders::find(name)})});
    };
    const auto copy = pipeline("bench/copy_rgba16f");
    const auto copySkip = pipeline("bench/copy_skip_rgba16f");

    std::vector<CompileRow> compiles;
    for (const uint32_t passes : {100u, 1000u}) {
        std::printf("[graph] compile %u passes ... ", passes);
        std::fflush(stdout);
        compiles.push_back(benchCompile(device, copySkip, passes, options.compiles));
        std::printf("median %.3f ms\n", compiles.back().compileMs.median);
    }
    std::vector<OverheadResult> overheads;
    bool verified = true;
    // 1280x720: the real case. 16x16: the same recording with next to no GPU work, so
    // that on lavapipe little else runs on the CPU between two recordings.
    // The small case takes ten times the frames: they are cheap, and its figures are small.
    for (const Extent2D size : {Extent2D{1280, 720}, Extent2D{16, 16}}) {
        const uint32_t scale = size.width < 100 ? 10 : 1;
        std::printf("[graph] overhead: 20-pass chain at %ux%u, %u frames ... ", size.width, size.height,
                    scale * options.frames);
        std::fflush(stdout);
        overheads.push_back(benchOverhead(device, copy, scale * options.warmup, scale * options.frames, 20, size));
        verified = verified && overheads.back().verified;
        std::printf("graph / hand = %.3f\n", overheads.back().executeRatio);
    }
    const MemoryRow memory = benchMemory(device, copy, 20, {1280, 720});

    printTables(compiles, overheads, memory);
    writeResults(options.output,
                        toJson(options, info, instance.validationEnabled(), compiles, overheads, memory));
    std::printf("[graph] wrote %s\n", options.output.c_str());
    if (!verified) {
        std::fprintf(stderr, "hush-bench-graph: the chains did not reproduce their input; figures are suspect\n");
        return 1;
    }
    if (size_t messages = instance.validationMessageCount(); messages != 0) {
        std::fprintf(stderr, "hush-bench-graph: %zu validation message(s)\n", messages);
        return 1;
    }
    return 0;
}

} // namespace
} // namespace hush::bench

int main(int argc, char** argv) {
    return hush::bench::guardedMain("hush-bench-graph", [&] {
        hush::bench::graph_bench::Options options;
        options.commandLine = hush::bench::commandLineOf(argc, argv);
        if (!hush::bench::parseOptions(argc, argv, options)) {
            std::printf("%.*s", int(hush::bench::kUsage.size()), hush::bench::kUsage.data());
            return 0;
        }
        return hush::bench::run(options);
    });
}
