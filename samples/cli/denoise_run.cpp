#include "denoise_run.hpp"

#include <hush/core/error.hpp>

#include "frame_upload.hpp"

namespace hush::cli {

DenoiseRun::DenoiseRun(rhi::Device device, std::unique_ptr<passes::Chain> chain, rhi::Extent2D size,
                       const std::vector<passes::InputChannel>& available)
    : runner_(std::move(device), std::move(chain), size, {}, available), passNames_(runner_.graph().passOrder()) {}

DenoisedFrame DenoiseRun::process(const tracer::Frame& frame) {
    const auto size = runner_.inputs().size();
    if (frame.width != size.width || frame.height != size.height)
        throw Error(ErrorKind::InvalidArgument, "frame " + std::to_string(frame.index) + " is " +
                                                    std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                                                    ", the sequence started at " + std::to_string(size.width) + "x" +
                                                    std::to_string(size.height));
    frames::uploadFrame(runner_, frame);
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
