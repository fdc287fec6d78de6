#include <hush/passes/rdae/architecture.hpp>

#include <cmath>

#include <hush/core/error.hpp>
#include <hush/passes/rdae/input.hpp>

namespace hush::passes {

uint32_t RdaeArchitecture::features(uint32_t level) const {
    // Sec. 4.1: "32 per pixel in the first stage ... multiply the number by 4/3 after
    // every subsampling". Rounded half up, as the training toolkit does.
    return uint32_t(std::floor(double(width) * std::pow(4.0 / 3.0, double(level)) + 0.5));
}

std::vector<RdaeConvShape> RdaeArchitecture::convolutions() const {
    std::vector<RdaeConvShape> convs;
    uint32_t previous = kRdaeInputChannels;
    for (uint32_t k = 0; k < levels; ++k) {
        const std::string stage = "encoders." + std::to_string(k);
        const uint32_t f = features(k);
        convs.push_back({stage + ".conv", k, previous, 0, f});
        // h_i = C(C(C(I_i) concat h_{i-1})) (Sec. 4.2)
        convs.push_back({stage + ".rcnn.input", k, f, 0, f});
        convs.push_back({stage + ".rcnn.mix", k, f, f, f});
        convs.push_back({stage + ".rcnn.output", k, f, 0, f});
        previous = f;
    }
    convs.push_back({"bottleneck", levels, previous, 0, features(levels)});
    previous = features(levels);
    for (uint32_t k = levels - 1; k >= 1; --k) {
        const std::string stage = "decoders." + std::to_string(k);
        convs.push_back({stage + ".conv1", k, previous, features(k), features(k)});
        convs.push_back({stage + ".conv2", k, features(k), 0, features(k)});
        previous = features(k);
    }
    convs.push_back({"final", 0, previous, features(0), kRdaeOutputChannels, true});
    return convs;
}

uint64_t RdaeArchitecture::parameterCount() const {
    uint64_t n = 0;
    for (const auto& c : convolutions()) n += 9ull * (c.inputA + c.inputB) * c.outputs + c.outputs;
    return n;
}

double RdaeArchitecture::multiplyAddsPerPixel() const {
    double n = 0.0;
    for (const auto& c : convolutions()) n += 9.0 * (c.inputA + c.inputB) * c.outputs / std::pow(4.0, c.level);
    return n;
}

void RdaeArchitecture::validate() const {
    if (width < 1 || width > 256)
        throw Error(ErrorKind::InvalidArgument, "rdae: width " + std::to_string(width) + " is outside [1, 256]");
    if (levels < 1 || levels > 8)
        throw Error(ErrorKind::InvalidArgument, "rdae: levels " + std::to_string(levels) + " is outside [1, 8]");
}

} // namespace hush::passes
