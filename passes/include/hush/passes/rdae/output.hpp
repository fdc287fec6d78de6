#pragma once
// The RDAE's way back from its output layer (shaders/rdae/output.comp): crop the
// padded tensor to the frame and undo the input's power 0.2 (x^5), giving the filtered
// demodulated illumination, rgba32f at the output size.
#include <string>

#include <hush/passes/node_context.hpp>
#include <hush/passes/rdae/tensor.hpp>

namespace hush::passes {

// Adds pass "<name>"; `features`: the output layer's 3 channels at level 0.
graph::TextureHandle addRdaeOutputPass(NodeContext& ctx, const std::string& name, const RdaeTensor& features);

} // namespace hush::passes
