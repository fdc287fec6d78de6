#pragma once
// Inputs for the BMFR fit tests: a node run and synthetic scenes.
#include <cmath>
#include <string>

#include <hush/passes/bmfr/fit.hpp>

#include "pass_test_util.hpp"
#include "reference/bmfr_fit.hpp"

namespace hush::passes_test::bmfr {

struct Scene {
    FloatImage illumination, normal, position, albedo, roughness, meshId;
    FloatImage clean;   // the illumination before the noise (realLookingScene)
    reference::BmfrImages images() const {
        return {&illumination, &normal, &position, &albedo, &roughness, &meshId};
    }
    uint32_t width() const { return illumination.width; }
    uint32_t height() const { return illumination.height; }
};

// Random everything (features and colour uniform in [-1, 1] / [0, 1)).
inline Scene randomScene(uint32_t w, uint32_t h, uint64_t seed) {
    Scene s;
    s.illumination = randomImage(w, h, 3, 0.0f, 1.0f, seed);
    s.normal = randomImage(w, h, 3, -1.0f, 1.0f, seed + 1);
    s.position = randomImage(w, h, 3, -4.0f, 4.0f, seed + 2);
    s.albedo = randomImage(w, h, 3, 0.0f, 1.0f, seed + 3);
    s.roughness = randomImage(w, h, 1, 0.0f, 1.0f, seed + 4);
    s.meshId = makeImage(w, h, 1, [](uint32_t x, uint32_t y, uint32_t) { return float((x / 7 + y / 5) % 3); });
    return s;
}

// A floor (y = 0) in the bottom part and a sphere-ish bump above it, seen from a
// camera at (0, 2, -6); smooth lighting from a point light, times 1 +- 50 % noise.
inline Scene realLookingScene(uint32_t w, uint32_t h, uint64_t seed) {
    Scene s = randomScene(w, h, seed);
    const auto jitter = randomImage(w, h, 1, 0.5f, 1.5f, seed + 9);
    s.clean = FloatImage(w, h, 3);
    const double lx = 1.0, ly = 3.0, lz = 1.0;
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            const double u = (x + 0.5) / w * 2.0 - 1.0, v = (y + 0.5) / h * 2.0 - 1.0;
            double n[3], p[3];
            const double r2 = u * u + (v + 0.2) * (v + 0.2);
            if (r2 < 0.36) {   // sphere of radius 1 around (0, 1, 0), seen head-on
                const double nx = u / 0.6, ny = -(v + 0.2) / 0.6, nz = -std::sqrt(std::max(0.0, 1.0 - nx * nx - ny * ny));
                n[0] = nx, n[1] = ny, n[2] = nz;
                p[0] = nx, p[1] = 1.0 + ny, p[2] = nz;
            } else {           // floor: depth grows towards the top of the image
                n[0] = 0, n[1] = 1, n[2] = 0;
                p[0] = u * 4.0, p[1] = 0.0, p[2] = 2.0 - v * 6.0;
            }
            const double dx = lx - p[0], dy = ly - p[1], dz = lz - p[2];
            const double d2 = dx * dx + dy * dy + dz * dz, d = std::sqrt(d2);
            const double lambert = std::max(0.0, (n[0] * dx + n[1] * dy + n[2] * dz) / d);
            const double light = 0.05 + 8.0 * lambert / d2;
            for (uint32_t c = 0; c < 3; ++c) {
                s.normal.at(x, y, c) = float(n[c]);
                s.position.at(x, y, c) = float(p[c]);
                s.clean.at(x, y, c) = float(light * (c == 0 ? 1.0 : c == 1 ? 0.8 : 0.6));
                s.illumination.at(x, y, c) = s.clean.at(x, y, c) * jitter.at(x, y);
            }
        }
    }
    return s;
}

// Runs the node for `frames` frames and returns the last frame's output.
inline FloatImage runFit(const Scene& sc, const passes::BmfrFitSettings& s, uint32_t frames = 1) {
    NodeHarness t({sc.width(), sc.height()}, "bmfr-fit-test");
    passes::BmfrGuide g;
    g.normal = t.input("normal", sc.normal);
    g.position = t.input("position", sc.position);
    g.albedo = t.input("albedo", sc.albedo);
    g.roughness = t.input("roughness", sc.roughness, rhi::Format::R32Float);
    g.meshId = t.input("meshid", sc.meshId, rhi::Format::R32Float);
    auto out = passes::addBmfrFitPass(t.ctx, "bmfr.fit", t.input("illumination", sc.illumination), g, s);
    t.graph.markOutput(out);
    for (uint32_t f = 0; f < frames; ++f) t.graph.execute();
    t.graph.waitIdle();
    return readOutput(t.graph, out);
}

// Largest |a - b| over rgb, and the RMS of b's rgb (the error's scale).
struct Diff {
    double maxAbs = 0.0, rms = 0.0, scale = 0.0;
};
inline Diff diff(const FloatImage& a, const FloatImage& b) {
    Diff d;
    double sum = 0.0, ref = 0.0;
    for (uint32_t y = 0; y < a.height; ++y) {
        for (uint32_t x = 0; x < a.width; ++x) {
            for (uint32_t c = 0; c < 3; ++c) {
                const double e = std::fabs(double(a.at(x, y, c)) - double(b.at(x, y, c)));
                d.maxAbs = std::isnan(e) ? INFINITY : std::max(d.maxAbs, e);
                sum += e * e;
                ref += double(b.at(x, y, c)) * b.at(x, y, c);
            }
        }
    }
    const double n = 3.0 * a.width * a.height;
    d.rms = std::sqrt(sum / n);
    d.scale = std::sqrt(ref / n);
    return d;
}

} // namespace hush::passes_test::bmfr
