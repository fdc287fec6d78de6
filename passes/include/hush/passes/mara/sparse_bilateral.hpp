#pragma once
// Mara et al. 2017's sparse cross-bilateral filter (seed 000 Sec. 3.4, stages 4 and 7;
// docs/passes/mara.md): `taps` taps on a spiral over a disk, turned per pixel and per
// frame (a blue-noise-like pattern that varies in time), Gaussian over the disk
// (sigma = radius / 2), each tap weighted by its distance from the centre's tangent
// plane (relative to depth) and by normal agreement. Pixels without a surface pass
// through. Stage 4 uses a fixed radius (a disk of diameter 1% of the image width),
// stage 7 the per-pixel radius of the disocclusion stage.
#include <cstdint>
#include <string>

#include <hush/passes/common/surface.hpp>
#include <hush/passes/node_context.hpp>
#include <hush/passes/settings.hpp>

namespace hush::passes {

struct MaraSparseBilateralSettings {
    uint32_t taps = 50;          // Sec. 3.4: "only 50 taps"
    float diameter = 0.01f;      // of the image width (Sec. 3.4: "diameter equal to 1% of the screen width")
    // Turns of the spiral over the disk. McGuire et al. 2012 pick a number of turns
    // per tap count so that taps do not line up; 7 does that for 50 taps.
    float spiralTurns = 7.0f;
    // Tap weight: exp(-(plane distance / (planeSigma * depth))^2) * max(0, n.n')^normalPower.
    // The paper names the plane test, not its scale: 2% of the depth, and a 30 degree
    // crease weighs 0.87^32 = 0.01.
    float planeSigma = 0.02f;
    float normalPower = 32.0f;
};

template <class V> void describe(V&& v, MaraSparseBilateralSettings& s) {
    v.field("taps", s.taps, Range{1, 256});
    v.field("diameter", s.diameter, Range{0.0, 1.0});
    v.field("spiralTurns", s.spiralTurns, Range{0.0, 1000.0});
    v.field("planeSigma", s.planeSigma, Range{1e-6, kUnbounded});
    v.field("normalPower", s.normalPower, Range{0.0, 1024.0});
}

// Adds pass "<name>"; returns the filtered rgb (alpha copied), rgba32f "<name>".
// `radius`: an r32f map of radii in pixels (stage 7), or invalid for the settings'
// diameter (stage 4). `position` is world xyz.
graph::TextureHandle addMaraSparseBilateralPass(NodeContext& ctx, const std::string& name, graph::TextureHandle color,
                                                const Surface& surface, graph::TextureHandle position,
                                                graph::TextureHandle radius,
                                                const MaraSparseBilateralSettings& settings = {});

} // namespace hush::passes
