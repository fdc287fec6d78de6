#pragma once
// Mara et al. 2017 stage 6, firefly suppression (seed 000 Sec. 3.4): a 3x3 median, per
// channel (edge pixels repeat), on the temporal output outside the history loop, "to
// ensure those samples still affect the running average but do not appear on screen".
#include <string>

#include <hush/passes/node_context.hpp>

namespace hush::passes {

// Adds pass "<name>"; returns the per-channel median of rgb (alpha copied), rgba32f "<name>".
graph::TextureHandle addMaraMedianPass(NodeContext& ctx, const std::string& name, graph::TextureHandle color);

} // namespace hush::passes
