#include "temporal_artifacts.hpp"

#include <algorithm>
#include <cmath>

namespace hush::cli {

void DisocclusionAge::update(const tracer::Frame& frame, bool reset) {
    const auto& motion = frame.get(tracer::Channel::Motion);
    const auto& meshId = frame.get(tracer::Channel::MeshId).pixels;
    const auto& depth = frame.get(tracer::Channel::Depth).pixels;
    const bool fresh = reset || frame.width != width_ || frame.height != height_;
    std::vector<uint8_t> age(size_t(frame.width) * frame.height, 0);
    if (!fresh) {
        for (uint32_t y = 0; y < frame.height; ++y)
            for (uint32_t x = 0; x < frame.width; ++x) {
                const size_t i = size_t(y) * frame.width + x;
                const float* m = &motion.pixels[i * motion.channels];
                const auto px = int64_t(std::floor(float(x) + 0.5f + m[0]));
                const auto py = int64_t(std::floor(float(y) + 0.5f + m[1]));
                if (px < 0 || py < 0 || px >= int64_t(width_) || py >= int64_t(height_)) continue;
                const size_t j = size_t(py) * width_ + size_t(px);
                const bool sameSurface = meshId[i] == meshId_[j] && meshId[i] >= 0.0f &&
                                         std::fabs(depth[i] - depth_[j]) <= 0.05f * depth[i];
                if (sameSurface) age[i] = uint8_t(std::min<int>(age_[j] + 1, 255));
            }
    }
    width_ = frame.width, height_ = frame.height;
    age_ = std::move(age);
    meshId_ = meshId;
    depth_ = depth;
}

std::vector<uint8_t> DisocclusionAge::recentMask() const {
    std::vector<uint8_t> mask(age_.size());
    for (size_t i = 0; i < age_.size(); ++i) mask[i] = age_[i] < kRecentFrames ? 1 : 0;
    return mask;
}

double maskedRmse(const RgbaImage& a, const RgbaImage& b, const std::vector<uint8_t>& mask, bool inside) {
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < mask.size(); ++i) {
        if ((mask[i] != 0) != inside) continue;
        for (size_t c = 0; c < 3; ++c) {
            const double d = double(a.rgba[i * 4 + c]) - double(b.rgba[i * 4 + c]);
            if (std::isfinite(d)) sum += d * d, ++n;
        }
    }
    return n ? std::sqrt(sum / double(n)) : -1.0;
}

} // namespace hush::cli
