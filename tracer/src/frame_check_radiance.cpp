// The shading conventions: albedo is reflectance in [0, 1] without lighting, and
// radiance is linear HDR, color = direct + indirect (docs/frame-format.md, Layers).
#include <cmath>

#include "frame_check_detail.hpp"

namespace hush::tracer::detail {
namespace {

float luminance(glm::vec3 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

// High-frequency energy relative to the signal, over pixels inside one surface: near
// zero for a noise-free layer, large for 1-sample radiance.
struct Roughness {
    double deviation = 0.0, signal = 0.0;
    void add(const Image& image, uint32_t x, uint32_t y) {
        const glm::vec3 around = (texel3(image, x - 1, y) + texel3(image, x + 1, y) + texel3(image, x, y - 1) +
                                  texel3(image, x, y + 1)) * 0.25f;
        const glm::vec3 here = texel3(image, x, y);
        if (!std::isfinite(luminance(here)) || !std::isfinite(luminance(around))) return;
        deviation += std::fabs(luminance(here - around));
        signal += std::fabs(luminance(here));
    }
    double relative() const { return signal > 0.0 ? deviation / signal : 0.0; }
};

bool insideOneSurface(const Frame& frame, const std::vector<uint8_t>& hit, uint32_t x, uint32_t y) {
    if (x == 0 || y == 0 || x + 1 >= frame.width || y + 1 >= frame.height) return false;
    const uint32_t w = frame.width;
    const size_t i = size_t(y) * w + x;
    if (!hit[i] || !hit[i - 1] || !hit[i + 1] || !hit[i - w] || !hit[i + w]) return false;
    if (!frame.has(Channel::MeshId)) return true;
    const auto& id = frame.get(Channel::MeshId).pixels;
    return id[i - 1] == id[i] && id[i + 1] == id[i] && id[i - w] == id[i] && id[i + w] == id[i];
}

} // namespace

ConventionCheck checkAlbedo(std::span<const Frame> frames) {
    std::string missing;
    if (lacks(frames, {Channel::Albedo}, missing)) return skipped("albedo", missing);
    uint64_t hits = 0, outside = 0;
    Roughness albedo, color;
    for (const Frame& frame : frames) {
        const std::vector<uint8_t> hit = hitMask(frame);
        const Image& a = frame.get(Channel::Albedo);
        for (uint32_t y = 0; y < frame.height; ++y) {
            for (uint32_t x = 0; x < frame.width; ++x) {
                if (!hit[size_t(y) * frame.width + x]) continue;
                const glm::vec3 value = texel3(a, x, y);
                ++hits;
                outside += !(glm::all(glm::greaterThanEqual(value, glm::vec3(-1e-3f))) &&
                             glm::all(glm::lessThanEqual(value, glm::vec3(1.001f))));
                if (!insideOneSurface(frame, hit, x, y)) continue;
                albedo.add(a, x, y);
                if (frame.has(Channel::Color)) color.add(frame.get(Channel::Color), x, y);
            }
        }
    }
    if (hits == 0) return skipped("albedo", "no pixel hits a surface");
    const double outsideRate = double(outside) / double(hits);
    std::string evidence = percent(outsideRate) + " of hit pixels outside [0, 1]";
    if (outsideRate > 0.005)
        return failed("albedo", evidence + ": albedo is reflectance, without lighting (is light multiplied in?)");
    if (color.signal > 0.0) {
        const double ratio = albedo.relative() / glm::max(color.relative(), 1e-12);
        evidence += "; pixel-to-pixel variation " + number(ratio, 2) + "x the colour's";
        if (ratio > 0.3) return failed("albedo", evidence + ": albedo is noisy like the radiance (is light multiplied in?)");
    }
    return passed("albedo", evidence + ": OK");
}

namespace {

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

struct RadianceTally {
    uint64_t values = 0, nonFinite = 0, negative = 0, atOne = 0;
    float largest = 0.0f;
    // color against direct + indirect, as stored and as if sRGB-decoded
    double partsError = 0.0, partsErrorDecoded = 0.0, partsSignal = 0.0, partsSignalDecoded = 0.0;
};

void tallyRadiance(const Frame& frame, RadianceTally& t) {
    const auto& c = frame.get(Channel::Color).pixels;
    const bool parts = frame.has(Channel::Direct) && frame.has(Channel::Indirect) && !frame.has(Channel::Matte) &&
                       !frame.has(Channel::Glossy);   // in Mara mode direct is another estimator
    for (size_t i = 0; i < c.size(); ++i) {
        ++t.values;
        if (!std::isfinite(c[i])) {
            ++t.nonFinite;
            continue;
        }
        t.negative += c[i] < 0.0f;
        t.atOne += c[i] >= 0.999f && c[i] <= 1.0001f;
        t.largest = glm::max(t.largest, c[i]);
        if (!parts) continue;
        const float d = frame.get(Channel::Direct).pixels[i], ind = frame.get(Channel::Indirect).pixels[i];
        if (!std::isfinite(d) || !std::isfinite(ind)) continue;
        t.partsError += std::fabs(c[i] - (d + ind));
        t.partsSignal += std::fabs(c[i]);
        t.partsErrorDecoded += std::fabs(srgbToLinear(c[i]) - (srgbToLinear(d) + srgbToLinear(ind)));
        t.partsSignalDecoded += std::fabs(srgbToLinear(c[i]));
    }
}

} // namespace

ConventionCheck checkRadiance(std::span<const Frame> frames) {
    std::string missing;
    if (lacks(frames, {Channel::Color}, missing)) return skipped("radiance", missing);
    RadianceTally t;
    for (const Frame& frame : frames) tallyRadiance(frame, t);
    std::string evidence = "colour values: " + percent(double(t.nonFinite) / double(t.values)) + " NaN or infinite, " +
                           percent(double(t.negative) / double(t.values)) + " negative, largest " + number(t.largest);
    if (t.nonFinite > 0) return failed("radiance", evidence + ": the renderer wrote NaN or infinity (chains zero them, losing those pixels)");
    if (double(t.negative) / double(t.values) > 0.001) return failed("radiance", evidence + ": radiance is never negative");
    if (t.partsSignal > 0.0) {
        const double error = t.partsError / t.partsSignal;
        const double decoded = t.partsErrorDecoded / glm::max(t.partsSignalDecoded, 1e-30);
        evidence += "; color differs from direct + indirect by " + percent(error) + " (as sRGB-decoded values: " +
                    percent(decoded) + ")";
        if (error > 0.001 && decoded < 0.5 * error)
            return failed("radiance", evidence + ": the layers are sRGB-encoded; hush wants linear radiance");
        if (error > 0.01) return failed("radiance", evidence + ": color should be direct + indirect");
    }
    if (t.largest <= 1.0001f && double(t.atOne) / double(t.values) > 0.005)
        return failed("radiance", evidence + ", " + percent(double(t.atOne) / double(t.values)) +
                                      " exactly 1: clipped, so tone-mapped or display-encoded; hush wants linear HDR radiance");
    return passed("radiance", evidence + ": linear HDR OK");
}

} // namespace hush::tracer::detail
