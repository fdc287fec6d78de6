#pragma once
// One 3x3 convolution of the recurrent denoising autoencoder (Chaitanya et al. 2017,
// Eq. 1; shaders/rdae/conv.glsl): zero padding, bias, leaky ReLU (alpha 0.1) or
// linear. Its input is `a`, or `a` and `b` concatenated (a skip connection, the RCNN
// block's hidden state): the pass reads both tensors, nothing copies them.
#include <string>
#include <vector>

#include <hush/passes/node_context.hpp>
#include <hush/passes/rdae/tensor.hpp>
#include <hush/rhi/buffer.hpp>
#include <hush/rhi/device.hpp>

namespace hush::passes {

// A convolution's parameters as PyTorch's Conv2d holds them.
struct RdaeConvParameters {
    std::string name;            // the weights file's prefix, e.g. "encoders.0.conv"
    uint32_t inputs = 0;
    uint32_t outputs = 0;
    std::vector<float> weight;   // [outputs][inputs][3][3]
    std::vector<float> bias;     // [outputs]
};

// The same on the GPU, packed for conv.glsl: a mat4 per (output block, input block,
// tap), with the input channels split as inputA (padded to a block) then the rest.
struct RdaeConvWeights {
    std::string name;
    rhi::Buffer weights;
    rhi::Buffer bias;
    uint32_t inputA = 0;
    uint32_t inputB = 0;
    uint32_t outputs = 0;
};

// The packed layout, as floats (tests read it; uploadRdaeConv uploads it).
std::vector<float> packRdaeConvWeights(const RdaeConvParameters& conv, uint32_t inputA);
RdaeConvWeights uploadRdaeConv(const rhi::Device& device, const RdaeConvParameters& conv, uint32_t inputA);

enum class RdaeActivation : uint32_t { Linear = 0, LeakyRelu = 1 };

struct RdaeConvInputs {
    RdaeTensor a;
    RdaeTensor b;                // optional: concatenated after a's channels
    bool bIsHistory = false;     // b holds nothing (reads as zero) while the history is invalid
};

// Adds pass "<name>"; returns its output tensor "<name>" (weights.outputs channels,
// at a's level). Throws hush::Error naming the pass when the tensors' channels or
// levels do not match the weights.
RdaeTensor addRdaeConvPass(NodeContext& ctx, const std::string& name, const RdaeConvInputs& inputs,
                           const RdaeConvWeights& weights, RdaeActivation activation, const RdaeTensorFormat& format);

} // namespace hush::passes
