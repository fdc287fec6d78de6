#pragma once
// The RCNN block of Chaitanya et al. 2017 (Sec. 4.2, Fig. 2 right):
//   h_i = O_i = C(C(C(I_i) concat h_{i-1}))
// three 3x3 convolutions, the second reading the first's output and last frame's
// hidden state. The hidden state is a graph history of the third's output: it holds
// nothing (reads as zero) on the first frame and after resetHistory() (a camera cut).
#include <string>

#include <hush/passes/node_context.hpp>
#include <hush/passes/rdae/conv.hpp>

namespace hush::passes {

struct RdaeRecurrentWeights {
    const RdaeConvWeights* input = nullptr;    // C(I_i)
    const RdaeConvWeights* mix = nullptr;      // C(. concat h_{i-1})
    const RdaeConvWeights* output = nullptr;   // C(.) = h_i
};

// Adds passes "<name>.input", "<name>.mix", "<name>.output"; returns h_i (the texture
// "<name>.output", whose history is "<name>.hidden").
RdaeTensor addRdaeRecurrentBlock(NodeContext& ctx, const std::string& name, const RdaeTensor& input,
                                 const RdaeRecurrentWeights& weights, const RdaeTensorFormat& format);

} // namespace hush::passes
