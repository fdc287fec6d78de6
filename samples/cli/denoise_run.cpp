#include "denoise_run.hpp"

#include <hush/core/error.hpp>

namespace hush::cli {

tracer::Channel tracerChannel(passes::InputChannel channel) {
    const auto name = passes::inputChannelInfo(channel).name;
    auto c = tracer::parseChannel(name);
    if (!c) throw Error(ErrorKind::NotFound, "no frame layer called '" + std::string(name) + "'");
    return *c;
}

DenoiseRun::DenoiseRun(rhi::Device device, std::unique_ptr<passes::Chain> chain, rhi::Extent2D size)
    : runner_(std::move(device), std::move(chain), size), passNames_(runner_.graph().passOrder()) {}

DenoisedFrame DenoiseRun::process(const tracer::Frame& frame) {
    auto& inputs = runner_.inputs();
    const auto size = inputs.size();
    if (frame.width != size.width || frame.height != size.height)
        throw Error(ErrorKind::InvalidArgument, "frame " + std::to_string(frame.index) + " is " +
                                                    std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                                                    ", the sequence started at " + std::to_string(size.width) + "x" +
                                                    std::to_string(size.height));
    for (auto c : inputs.channels()) {
        const auto tc = tracerChannel(c);
        if (c == passes::InputChannel::Emission && !frame.has(tc)) {
            // A renderer that does not split off emission: none to take out.
            zeros_.assign(size_t(size.width) * size.height * 3, 0.0f);
            inputs.upload(c, zeros_, 3);
            continue;
        }
        if (!frame.has(tc)) {
            const bool lighting = c == passes::InputChannel::Direct || c == passes::InputChannel::Indirect;
            throw Error(ErrorKind::NotFound,
                        "frame " + std::to_string(frame.index) + " has no '" +
                            std::string(passes::inputChannelInfo(c).name) + "' layer, which chain '" +
                            runner_.chain().name() + "' reads" +
                            (lighting ? " (render with direct and indirect, or filter the colour as one term with a "
                                        "chain file: {\"base\": \"svgf\", \"settings\": {\"splitLighting\": false}})"
                                      : ""));
        }
        const auto& image = frame.get(tc);
        inputs.upload(c, image.pixels, image.channels);
    }
    runner_.run();

    DenoisedFrame out;
    out.display = RgbaImage(size.width, size.height);
    out.display.rgba = runner_.readDisplay();
    out.radiance = RgbaImage(size.width, size.height);
    out.radiance.rgba = runner_.readRadiance();
    for (auto n : runner_.sanitizedCounts()) out.sanitized += n;
    const auto& t = runner_.graph().timings();
    if (t.valid) {
        for (const auto& p : t.passes) passMs_[p.name].push_back(p.gpuMs);
        frameMs_.push_back(t.totalGpuMs);
    }
    return out;
}

} // namespace hush::cli
