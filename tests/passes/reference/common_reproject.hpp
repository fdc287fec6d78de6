#pragma once
// CPU reference of passes/common/reproject: the decision texture and reading a
// history through it, written from the encoding in reproject.hpp and SVGF Sec. 4.1.
#include <array>

#include <hush/passes/common/reproject.hpp>

#include "reference/common_surface.hpp"

namespace hush::passes_test::reference {

// The decision image (4 channels: xy, mask, mode) for a motion image (2+ channels)
// and this and last frame's packed surfaces.
FloatImage reproject(const FloatImage& motion, const SurfaceImages& current, const SurfaceImages& previous,
                     const passes::ReprojectSettings& settings, bool historyValid);

// `history` (4 channels) at one pixel through its decision: false where
// disoccluded; else the renormalised weighted value.
bool fetchReprojected(const FloatImage& history, const FloatImage& decision, uint32_t x, uint32_t y,
                      std::array<float, 4>& value);

// The decision a static camera over an unchanged surface gives: every pixel mode 1,
// its own texel only (xy = pixel, mask 1).
FloatImage identityDecision(uint32_t width, uint32_t height);

} // namespace hush::passes_test::reference
