#include "rdae_test_util.hpp"

#include <cmath>
#include <cstring>
#include <sstream>

#include <hush/core/json.hpp>

namespace hush::passes_test {

Tensor randomTensor(uint32_t channels, uint32_t width, uint32_t height, float lo, float hi, uint64_t seed) {
    Tensor t(channels, width, height);
    test::Lcg lcg(seed);
    for (auto& v : t.values) v = lcg.uniform(lo, hi);
    return t;
}

FloatImage packTensor(const Tensor& t) {
    const auto l = passes::rdaeTensorLayout(t.channels);
    FloatImage image(t.width * l.tilesX, t.height * l.tilesY, 4, 0.0f);
    for (uint32_t c = 0; c < t.channels; ++c) {
        const uint32_t b = c / 4, ox = (b % l.tilesX) * t.width, oy = (b / l.tilesX) * t.height;
        for (uint32_t y = 0; y < t.height; ++y)
            for (uint32_t x = 0; x < t.width; ++x) image.at(ox + x, oy + y, c % 4) = t.at(c, x, y);
    }
    return image;
}

Tensor unpackTensor(const FloatImage& texture, uint32_t channels, uint32_t width, uint32_t height) {
    const auto l = passes::rdaeTensorLayout(channels);
    REQUIRE(texture.width == width * l.tilesX);
    REQUIRE(texture.height == height * l.tilesY);
    Tensor t(channels, width, height);
    for (uint32_t c = 0; c < channels; ++c) {
        const uint32_t b = c / 4, ox = (b % l.tilesX) * width, oy = (b / l.tilesX) * height;
        for (uint32_t y = 0; y < height; ++y)
            for (uint32_t x = 0; x < width; ++x) t.at(c, x, y) = texture.at(ox + x, oy + y, c % 4);
    }
    return t;
}

passes::RdaeTensor importTensor(NodeHarness& h, const std::string& name, const Tensor& t, uint32_t level,
                                const passes::RdaeTensorFormat& format) {
    return {h.input(name, packTensor(t), format.format), t.channels, level};
}

Tensor runTensor(NodeHarness& h, const passes::RdaeTensor& t, uint32_t width, uint32_t height) {
    return unpackTensor(h.runOnce(t.texture), t.channels, width, height);
}

passes::RdaeConvParameters randomConv(const std::string& name, uint32_t inputs, uint32_t outputs, uint64_t seed) {
    passes::RdaeConvParameters p{.name = name, .inputs = inputs, .outputs = outputs};
    test::Lcg lcg(seed);
    const float scale = std::sqrt(2.0f / (9.0f * float(inputs)));   // He-like: activations stay O(1)
    for (size_t i = 0; i < size_t(outputs) * inputs * 9; ++i) p.weight.push_back(lcg.uniform(-1.7f, 1.7f) * scale);
    for (uint32_t o = 0; o < outputs; ++o) p.bias.push_back(lcg.uniform(-0.2f, 0.2f));
    return p;
}

std::string safetensorsBytes(const std::map<std::string, NamedTensor>& tensors,
                             const std::map<std::string, std::string>& metadata) {
    core::Json header = core::Json::object();
    std::string data;
    for (const auto& [name, t] : tensors) {
        const size_t begin = data.size();
        data.append(reinterpret_cast<const char*>(t.values.data()), t.values.size() * sizeof(float));
        header[name] = {{"dtype", "F32"}, {"shape", t.shape}, {"data_offsets", {begin, data.size()}}};
    }
    if (!metadata.empty()) header["__metadata__"] = metadata;
    const std::string text = header.dump();
    std::string bytes(8, '\0');
    uint64_t n = text.size();
    for (int i = 0; i < 8; ++i) bytes[size_t(i)] = char((n >> (8 * i)) & 0xFF);
    return bytes + text + data;
}

std::string compareTensors(const Tensor& gpu, const Tensor& reference, float absTol, float relTol) {
    if (gpu.values.size() != reference.values.size()) return "different sizes";
    double worst = -1.0;
    size_t at = 0;
    for (size_t i = 0; i < gpu.values.size(); ++i) {
        const double a = gpu.values[i], b = reference.values[i];
        const double excess = std::isnan(a) || std::isnan(b) ? 1e30 : std::abs(a - b) - (absTol + relTol * std::abs(b));
        if (excess > worst) worst = excess, at = i;
    }
    if (worst <= 0.0) return "";
    const size_t plane = size_t(gpu.width) * gpu.height;
    std::ostringstream s;
    s << "channel " << at / plane << " pixel (" << at % plane % gpu.width << ", " << at % plane / gpu.width
      << "): gpu " << gpu.values[at] << ", reference " << reference.values[at] << ", tolerance " << absTol << " + "
      << relTol << " |reference|";
    return s.str();
}

} // namespace hush::passes_test
