// hush-bench-tracer: the path tracer's speed on this machine. For every built-in
// scene at 640x360 and 1280x720: milliseconds per 1-spp frame (the default path:
// primary hit, one indirect bounce, two shadow rays) and Mrays/s, as medians of
// several frames; plus the time of a reference frame at a given spp. Prints a table
// and writes bench-results/tracer.json.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include <hush/core/error.hpp>
#include <hush/tracer/builtin_scenes.hpp>
#include <hush/tracer/renderer.hpp>

#include "bench_report.hpp"

using namespace hush;

namespace {

struct Options {
    uint32_t frames = 5;
    uint32_t referenceSpp = 64;
    std::string output = "bench-results/tracer.json";
    std::string commandLine;   // as given, for the results file
};

struct Row {
    std::string scene;
    uint32_t width, height;
    bench::Stats ms;
    double mrays;
    double referenceSeconds;
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
        else if (a == "--output") o.output = value("--output");
        else if (a == "--help") {
            std::printf("usage: hush-bench-tracer [--frames N (5)] [--reference-spp N (64)] [--output PATH]\n");
            std::exit(0);
        } else throw Error(ErrorKind::InvalidArgument, "unknown option '" + a + "' (try --help)");
    }
    return o;
}

double seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

} // namespace

int main(int argc, char** argv) {
    return bench::guardedMain("hush-bench-tracer", [&] {
        Options options = parse(argc, argv);
        options.commandLine = bench::commandLineOf(argc, argv);
        std::vector<Row> rows;
        std::printf("hush-bench-tracer on %s, %u threads\n\n", core::hostCpuName().c_str(),
                    std::max(1u, std::thread::hardware_concurrency()));
        std::printf("%-14s %-10s %12s %10s %10s %10s %16s\n", "scene", "size", "ms/frame", "min", "max", "Mrays/s",
                    "reference s");
        for (const auto& name : tracer::builtinSceneNames()) {
            const tracer::Renderer renderer(tracer::makeBuiltinScene(name));
            for (auto [w, h] : {std::pair{640u, 360u}, std::pair{1280u, 720u}}) {
                tracer::RenderSettings s;
                s.width = w;
                s.height = h;
                s.channels = {tracer::Channel::Color, tracer::Channel::Albedo, tracer::Channel::Normal,
                              tracer::Channel::Depth, tracer::Channel::Motion};
                std::vector<double> ms;
                const uint64_t raysBefore = renderer.raysTraced();
                double total = 0.0;
                for (uint32_t f = 0; f < options.frames; ++f) {
                    const auto start = std::chrono::steady_clock::now();
                    renderer.render(f, s);
                    const double t = seconds(start);
                    total += t;
                    ms.push_back(t * 1e3);
                }
                Row row{name, w, h, bench::summarize(ms), double(renderer.raysTraced() - raysBefore) / total * 1e-6, 0.0};
                if (w == 640 && options.referenceSpp) {
                    s.channels = {tracer::Channel::Reference};
                    s.referenceSpp = options.referenceSpp;
                    const auto start = std::chrono::steady_clock::now();
                    renderer.render(0, s);
                    row.referenceSeconds = seconds(start);
                }
                std::printf("%-14s %4ux%-5u %12.1f %10.1f %10.1f %10.2f %16s\n", name.c_str(), w, h, row.ms.median,
                            row.ms.min, row.ms.max, row.mrays,
                            row.referenceSeconds > 0 ? (std::to_string(row.referenceSeconds).substr(0, 6) + " @" +
                                                        std::to_string(options.referenceSpp) + "spp").c_str()
                                                     : "-");
                std::fflush(stdout);
                rows.push_back(row);
            }
        }
        std::string json = bench::resultsHead({.program = "tracer", .commandLine = options.commandLine, .device = {},
                                               .validation = false}) +
                           "  \"threads\": " + std::to_string(std::max(1u, std::thread::hardware_concurrency())) +
                           ",\n  \"framesPerSetting\": " + std::to_string(options.frames) + ",\n  \"referenceSpp\": " +
                           std::to_string(options.referenceSpp) + ",\n  \"rows\": [\n";
        for (size_t i = 0; i < rows.size(); ++i) {
            const auto& r = rows[i];
            char line[400];
            std::snprintf(line, sizeof line,
                          "    {\"scene\": %s, \"width\": %u, \"height\": %u, \"msMedian\": %.3f, \"msMin\": %.3f, "
                          "\"msMax\": %.3f, \"mraysPerSecond\": %.3f, \"referenceSeconds\": %.3f}%s\n",
                          bench::jsonString(r.scene).c_str(), r.width, r.height, r.ms.median, r.ms.min, r.ms.max, r.mrays,
                          r.referenceSeconds, i + 1 < rows.size() ? "," : "");
            json += line;
        }
        json += "  ]\n}\n";
        bench::writeResults(options.output, json);
        std::printf("\nwritten to %s\n", options.output.c_str());
        return 0;
    });
}
