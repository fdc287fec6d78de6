#pragma once
// Demodulation: filter illumination, not radiance, so that texture detail survives
// the blur (SVGF Sec. 3, BMFR Sec. 3, RDAE Sec. 3.2). Illumination = radiance /
// max(albedo, eps) per channel; a pixel whose albedo is below eps in every channel
// (emitters, black surfaces, background) keeps its radiance. Remodulation
// (common/remodulate.hpp) is the exact inverse.
//
// Emission seen at the primary hit is noise-free and much brighter than the light
// it sits beside; filtered with its neighbours it would bleed a halo around every
// emitter. With an `emission` input, demodulate takes it out (max(radiance -
// emission, 0)) and remodulate adds it back.
#include <string>

#include <hush/passes/settings.hpp>
#include <hush/passes/node_context.hpp>

namespace hush::passes {

struct DemodulateSettings {
    float eps = 1e-3f;
};

template <class V> void describe(V&& v, DemodulateSettings& s) { v.field("eps", s.eps, Range{1e-12, 1.0}); }

// Adds pass "<name>"; returns the illumination (rgba32f, transient "<name>").
// `emission` may be invalid (no emission to take out).
graph::TextureHandle addDemodulatePass(NodeContext& ctx, const std::string& name, graph::TextureHandle radiance,
                                       graph::TextureHandle albedo, const DemodulateSettings& settings = {},
                                       graph::TextureHandle emission = {});

} // namespace hush::passes
