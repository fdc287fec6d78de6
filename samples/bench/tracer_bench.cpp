// hush-bench-tracer: the path tracer's speed on this machine. For every built-in
// scene at 640x360 and 1280x720: milliseconds per 1-spp frame (the default path:
// primary hit, one indirect bounce, two shadow rays) and Mrays/s, as medians of
// several frames; plus the time of a reference frame at a given spp; and, as the
// roofline, Embree alone casting the same kinds of rays through the same BVH
// (probeRayCasting). Prints two tables and writes bench-results/tracer.json.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include <hush/core/error.hpp>
#include <hush/tracer/builtin_scenes.hpp>
#include <hush/tracer/ray_cast_probe.hpp>
#include <hush/tracer/renderer.hpp>

#include "bench_report.hpp"

using namespace hush;

namespace {

struct Options {
    uint32_t frames = 5;
    uint32_t referenceSpp = 64;
    uint32_t probeRepeats = 3;   // 0: no ray-casting probe
    std::string output = "bench-results/tracer.json";
    std::string commandLine;   // as given, for the results file
};

struct Row {
    std::string scene;
    uint32_t width, height;
    bench::Stats ms;
    double mrays;
    double referenceSeconds;
    tracer::RayCastRates embree;   // the probe's rates at the same size and frame
    double embreeSeconds = 0.0;    // the roofline: Embree alone on the frames' rays, at the probe's rates
    double seconds = 0.0;          // the frames' total
    uint64_t rays = 0;
    double ofRoofline() const { return embreeSeconds > 0 && seconds > 0 ? embreeSeconds / seconds : 0.0; }
    double embreeMrays() const { return embreeSeconds > 0 ? double(rays) / embreeSeconds * 1e-6 : 0.0; }
};

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&](const char* name) {
            if (i + 1 >= argc) throw Error(ErrorKind::InvalidArgument, std::string(name) + " needs a value");
            return std::string(argv[++i]);
        };
        if (a == "--frames") o.frames = core::parseCount(value("--frames"), "--frames", 1);
        else if (a == "--reference-spp") o.referenceSpp = core::parseCount(value("--reference-spp"), "--reference-spp", 0);
        else if (a == "--probe-repeats") o.probeRepeats = core::parseCount(value("--probe-repeats"), "--probe-repeats", 0);
        else if (a == "--output") o.output = value("--output");
        else if (a == "--help") {
            std::printf("usage: hush-bench-tracer [--frames N (5)] [--reference-spp N (64)] [--probe-repeats N (3; 0: none)]\n"
                        "                         [--output PATH]\n");
            std::exit(0);
        } else throw Error(ErrorKind::InvalidArgument, "unknown option '" + a + "' (try --help)");
    }
    return o;
}

double seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

Row measure(const tracer::Renderer& renderer, const std::string& name, uint32_t w, uint32_t h, const Options& options) {
    tracer::RenderSettings s;
    s.width = w;
    s.height = h;
    s.channels = {tracer::Channel::Color, tracer::Channel::Albedo, tracer::Channel::Normal, tracer::Channel::Depth,
                  tracer::Channel::Motion};
    std::vector<double> ms;
    const tracer::RayCounts before = renderer.raysCast();
    double total = 0.0;
    tracer::Frame frame;   // reused, as hush render does
    for (uint32_t f = 0; f < options.frames; ++f) {
        const auto start = std::chrono::steady_clock::now();
        renderer.renderInto(frame, f, s);
        const double t = seconds(start);
        total += t;
        ms.push_back(t * 1e3);
    }
    const tracer::RayCounts after = renderer.raysCast();
    const uint64_t primary = uint64_t(w) * h * options.frames, closest = after.closestHit - before.closestHit,
                   shadow = after.occlusion - before.occlusion;
    Row row{name, w, h, bench::summarize(ms), double(closest + shadow) / total * 1e-6, 0.0, {}};
    row.seconds = total;
    row.rays = closest + shadow;
    if (w == 640 && options.referenceSpp) {
        s.channels = {tracer::Channel::Reference};
        s.referenceSpp = options.referenceSpp;
        const auto start = std::chrono::steady_clock::now();
        renderer.render(0, s);
        row.referenceSeconds = seconds(start);
    }
    if (options.probeRepeats)
    {
        row.embree = tracer::probeRayCasting(renderer.scene(), {.frameIndex = 0, .width = w, .height = h,
                                                                .repeats = options.probeRepeats});
        row.embreeSeconds = row.embree.secondsFor(primary, closest > primary ? closest - primary : 0, shadow);
    }
    return row;
}

void printRow(const Row& row, const Options& options) {
    const double of = row.ofRoofline();
    std::printf("%-14s %4ux%-5u %12.1f %10.1f %10.1f %10.2f %12.2f %8s %16s\n", row.scene.c_str(), row.width, row.height,
                row.ms.median, row.ms.min, row.ms.max, row.mrays, row.embreeMrays(),
                of > 0 ? (std::to_string(int(of * 100.0 + 0.5)) + " %").c_str() : "-",
                row.referenceSeconds > 0 ? (std::to_string(row.referenceSeconds).substr(0, 6) + " @" +
                                            std::to_string(options.referenceSpp) + "spp").c_str()
                                         : "-");
    std::fflush(stdout);
}

void printProbeTable(const std::vector<Row>& rows) {
    std::printf("\nEmbree alone (probeRayCasting, frame 0), Mrays/s: primary rays one at a time and in packets of 8,\n"
                "bounce (closest hit) and shadow (occlusion) rays from the primary hits, and the same rays as the\n"
                "tracer cast (its primary, bounce and shadow counts) at these rates: the first table's roofline\n\n");
    std::printf("%-14s %-10s %10s %10s %10s %10s %10s\n", "scene", "size", "primary", "packet8", "bounce", "shadow", "as cast");
    for (const auto& r : rows)
        std::printf("%-14s %4ux%-5u %10.2f %10.2f %10.2f %10.2f %10.2f\n", r.scene.c_str(), r.width, r.height,
                    r.embree.primary, r.embree.primaryPacket, r.embree.bounce, r.embree.shadow, r.embreeMrays());
}

std::string resultsJson(const std::vector<Row>& rows, const Options& options) {
    std::string json = bench::resultsHead({.program = "tracer", .commandLine = options.commandLine, .device = {},
                                           .validation = false}) +
                       "  \"threads\": " + std::to_string(std::max(1u, std::thread::hardware_concurrency())) +
                       ",\n  \"framesPerSetting\": " + std::to_string(options.frames) + ",\n  \"referenceSpp\": " +
                       std::to_string(options.referenceSpp) + ",\n  \"probeRepeats\": " +
                       std::to_string(options.probeRepeats) + ",\n  \"rows\": [\n";
    for (size_t i = 0; i < rows.size(); ++i) {
        const auto& r = rows[i];
        char line[700];
        std::snprintf(line, sizeof line,
                      "    {\"scene\": %s, \"width\": %u, \"height\": %u, \"msMedian\": %.3f, \"msMin\": %.3f, "
                      "\"msMax\": %.3f, \"mraysPerSecond\": %.3f, \"referenceSeconds\": %.3f, \"embreeMrays\": "
                      "{\"primary\": %.3f, \"primaryPacket8\": %.3f, \"bounce\": %.3f, \"shadow\": %.3f, \"asCast\": %.3f}, \"ofRoofline\": %.4f}%s\n",
                      bench::jsonString(r.scene).c_str(), r.width, r.height, r.ms.median, r.ms.min, r.ms.max, r.mrays,
                      r.referenceSeconds, r.embree.primary, r.embree.primaryPacket, r.embree.bounce, r.embree.shadow,
                      r.embreeMrays(), r.ofRoofline(), i + 1 < rows.size() ? "," : "");
        json += line;
    }
    return json + "  ]\n}\n";
}

} // namespace

int main(int argc, char** argv) {
    return bench::guardedMain("hush-bench-tracer", [&] {
        Options options = parse(argc, argv);
        options.commandLine = bench::commandLineOf(argc, argv);
        std::vector<Row> rows;
        std::printf("hush-bench-tracer on %s, %u threads\n\n", core::hostCpuName().c_str(),
                    std::max(1u, std::thread::hardware_concurrency()));
        std::printf("%-14s %-10s %12s %10s %10s %10s %12s %8s %16s\n", "scene", "size", "ms/frame", "min", "max",
                    "Mrays/s", "Embree", "of it", "reference s");
        for (const auto& name : tracer::builtinSceneNames()) {
            const tracer::Renderer renderer(tracer::makeBuiltinScene(name));
            for (auto [w, h] : {std::pair{640u, 360u}, std::pair{1280u, 720u}}) {
                rows.push_back(measure(renderer, name, w, h, options));
                printRow(rows.back(), options);
            }
        }
        if (options.probeRepeats) printProbeTable(rows);
        bench::writeResults(options.output, resultsJson(rows, options));
        std::printf("\nwritten to %s\n", options.output.c_str());
        return 0;
    });
}
