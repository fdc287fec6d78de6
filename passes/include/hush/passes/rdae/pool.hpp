#pragma once
// RDAE 2x2 max pooling (Chaitanya et al. 2017, Fig. 2; shaders/rdae/pool.glsl): a
// tensor at level k to level k + 1, every channel.
#include <string>

#include <hush/passes/node_context.hpp>
#include <hush/passes/rdae/tensor.hpp>

namespace hush::passes {

// Adds pass "<name>"; returns "<name>", `features`' channels at its level + 1.
RdaeTensor addRdaePoolPass(NodeContext& ctx, const std::string& name, const RdaeTensor& features,
                           const RdaeTensorFormat& format);

} // namespace hush::passes
