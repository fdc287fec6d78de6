#pragma once
// Demodulation: filter illumination, not radiance, so that texture detail survives
// the blur (SVGF Sec. 3, BMFR Sec. 3, RDAE Sec. 3.2). Illumination = radiance /
// max(albedo, eps) per channel; a pixel whose albedo is below eps in every channel
// (emitters, black surfaces, background) keeps its radiance. Remodulation is the
// exact inverse, over one or two filtered terms (direct + indirect).
//
// Emission seen at the primary hit is noise-free and much brighter than the light
// it sits beside; filtered with its neighbours it would bleed a halo around every
// emitter. With an `emission` input, demodulate takes it out (max(radiance -
// emission, 0)) and remodulate adds it back.
#include <string>

#include <hush/passes/node_context.hpp>

namespace hush::passes {

struct DemodulateSettings {
    float eps = 1e-3f;
};

// Adds pass "<name>"; returns the illumination (rgba32f, transient "<name>").
// `emission` may be invalid (no emission to take out).
graph::TextureHandle addDemodulatePass(NodeContext& ctx, const std::string& name, graph::TextureHandle radiance,
                                       graph::TextureHandle albedo, const DemodulateSettings& settings = {},
                                       graph::TextureHandle emission = {});

// Adds pass "<name>": (a + b) * factor(albedo) + emission; b and emission optional
// (invalid handles).
graph::TextureHandle addRemodulatePass(NodeContext& ctx, const std::string& name, graph::TextureHandle a,
                                       graph::TextureHandle b, graph::TextureHandle albedo,
                                       const DemodulateSettings& settings = {},
                                       graph::TextureHandle emission = {});

} // namespace hush::passes
