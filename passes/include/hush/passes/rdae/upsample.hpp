#pragma once
// RDAE 2x2 nearest-neighbour upsampling (Chaitanya et al. 2017, Fig. 2;
// shaders/rdae/upsample.glsl): a tensor at level k + 1 to level k, every channel.
#include <string>

#include <hush/passes/node_context.hpp>
#include <hush/passes/rdae/tensor.hpp>

namespace hush::passes {

// Adds pass "<name>"; returns "<name>", `features`' channels at its level - 1.
RdaeTensor addRdaeUpsamplePass(NodeContext& ctx, const std::string& name, const RdaeTensor& features,
                               const RdaeTensorFormat& format);

} // namespace hush::passes
