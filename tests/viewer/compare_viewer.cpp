// Compares hush-viewer's headless output (an engine recording hush into its own
// command buffers, on its own device and images) with ChainRunner's on the same
// frames: the display images must be identical.
// Usage: compare_viewer <frames> <viewer output> <chain>
#include <cmath>
#include <cstdio>
#include <string>

#include <hush/core/error.hpp>
#include <hush/passes/chain_file.hpp>
#include <hush/passes/chain_runner.hpp>
#include <hush/rhi/rhi.hpp>
#include <hush/tracer/frame_io.hpp>

#include "frame_upload.hpp"

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: compare_viewer <frames> <viewer output> <chain>\n");
        return 2;
    }
    try {
        using namespace hush;
        const auto inputs = tracer::listFrames(argv[1]);
        const auto outputs = tracer::listFrames(argv[2]);
        if (outputs.size() != inputs.size()) {
            std::fprintf(stderr, "FAIL: %zu viewer frames for %zu inputs\n", outputs.size(), inputs.size());
            return 1;
        }
        auto instance = rhi::Instance::create();
        auto device = instance.requestAdapter().createDevice({.label = "compare_viewer"});
        const tracer::Frame first = tracer::readFrame(inputs[0]);
        passes::ChainRunner runner(device, passes::makeChain(argv[3]), {first.width, first.height}, {},
                                   frames::channelsOf(first));
        double worst = 0.0;
        for (size_t f = 0; f < inputs.size(); ++f) {
            frames::uploadFrame(runner, tracer::readFrame(inputs[f]));
            runner.run();
            const auto display = runner.readDisplay();
            const tracer::Frame viewer = tracer::readFrame(outputs[f], {.channels = {tracer::Channel::Color}});
            const auto& color = viewer.get(tracer::Channel::Color).pixels;
            for (size_t p = 0; p < size_t(first.width) * first.height; ++p)
                for (size_t c = 0; c < 3; ++c) worst = std::fmax(worst, std::fabs(double(color[p * 3 + c]) - display[p * 4 + c]));
        }
        std::printf("%s: %zu frames, largest difference between hush-viewer and ChainRunner %g\n", argv[3], inputs.size(), worst);
        if (worst != 0.0) {
            std::fprintf(stderr, "FAIL: the viewer's display differs from ChainRunner's\n");
            return 1;
        }
        if (instance.validationMessageCount() != 0) return 1;
        return 0;
    } catch (const hush::Error& e) {
        std::fprintf(stderr, "compare_viewer: %s\n", e.what());
        return 2;
    }
}
