#pragma once
// Pooling and upsampling are the same pass around different kernels: one tensor in,
// the same channels out at a neighbouring level, one z slice per channel block.
#include <string>

#include <hush/passes/node_context.hpp>
#include <hush/passes/rdae/tensor.hpp>

namespace hush::passes::detail {

RdaeTensor addRdaeResamplePass(NodeContext& ctx, const std::string& name, const std::string& kernel,
                               const std::string& outputPort, const RdaeTensor& features, uint32_t outputLevel,
                               const RdaeTensorFormat& format);

} // namespace hush::passes::detail
