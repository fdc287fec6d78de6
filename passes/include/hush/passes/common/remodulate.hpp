#pragma once
// Remodulation: the exact inverse of demodulation (common/demodulate.hpp), over one
// or two filtered lighting terms (direct + indirect): radiance = (a + b) *
// max(albedo, eps) + emission, with demodulation's rule for albedo below eps.
#include <string>

#include <hush/passes/common/demodulate.hpp>
#include <hush/passes/node_context.hpp>

namespace hush::passes {

// Adds pass "<name>": (a + b) * factor(albedo) + emission; b and emission optional
// (invalid handles).
graph::TextureHandle addRemodulatePass(NodeContext& ctx, const std::string& name, graph::TextureHandle a,
                                       graph::TextureHandle b, graph::TextureHandle albedo,
                                       const DemodulateSettings& settings = {},
                                       graph::TextureHandle emission = {});

} // namespace hush::passes
