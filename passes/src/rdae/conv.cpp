#include <hush/passes/rdae/conv.hpp>

#include <algorithm>
#include <cstring>

#include <hush/core/error.hpp>

#include "shader_variant.hpp"

namespace hush::passes {

namespace {

uint32_t blocksOf(uint32_t channels) { return (channels + 3) / 4; }

// conv.glsl computes output blocks in groups with a fixed loop: groups of 4, or of the
// layer's block count where it has fewer (the output layer's 3 channels are one block:
// a group of 4 spent 3/4 of its arithmetic on zero weights). The weights and biases are
// padded with zeros to whole groups.
constexpr uint32_t kMaxBlocksPerInvocation = 4;
constexpr uint32_t kPixels = 8;
uint32_t blocksPerInvocation(uint32_t outputs) {
    return std::min(kMaxBlocksPerInvocation, blocksOf(outputs));
}
uint32_t paddedOutputBlocks(uint32_t outputs) {
    const uint32_t group = blocksPerInvocation(outputs);
    return (blocksOf(outputs) + group - 1) / group * group;
}

// Where input channel i of the concatenation sits in the packed input blocks.
uint32_t packedInputChannel(uint32_t i, uint32_t inputA) {
    return i < inputA ? i : 4 * blocksOf(inputA) + (i - inputA);
}

rhi::Buffer uploadFloats(const rhi::Device& device, const std::string& label, const std::vector<float>& values) {
    auto buffer = device.createBuffer({.label = label, .size = values.size() * sizeof(float),
                                       .usage = rhi::BufferUsage::Storage | rhi::BufferUsage::CopyDst});
    device.queue().writeBuffer(buffer, 0, std::as_bytes(std::span(values)));
    return buffer;
}

void check(bool ok, const std::string& pass, const std::string& what) {
    if (!ok) throw Error(ErrorKind::InvalidArgument, "rdae convolution '" + pass + "': " + what);
}

} // namespace

std::vector<float> packRdaeConvWeights(const RdaeConvParameters& conv, uint32_t inputA) {
    const uint32_t inBlocks = blocksOf(inputA) + blocksOf(conv.inputs - inputA);
    const uint32_t outBlocks = paddedOutputBlocks(conv.outputs);
    std::vector<float> packed(size_t(outBlocks) * inBlocks * 9 * 16, 0.0f);
    for (uint32_t o = 0; o < conv.outputs; ++o)
        for (uint32_t i = 0; i < conv.inputs; ++i) {
            const uint32_t in = packedInputChannel(i, inputA);
            for (uint32_t tap = 0; tap < 9; ++tap) {
                const size_t matrix = (size_t(o / 4) * inBlocks + in / 4) * 9 + tap;
                // mat4 column (input component) then row (output component).
                packed[matrix * 16 + (in % 4) * 4 + o % 4] = conv.weight[(size_t(o) * conv.inputs + i) * 9 + tap];
            }
        }
    return packed;
}

RdaeConvWeights uploadRdaeConv(const rhi::Device& device, const RdaeConvParameters& conv, uint32_t inputA) {
    check(inputA <= conv.inputs, conv.name, "input a has more channels than the convolution");
    std::vector<float> bias(size_t(paddedOutputBlocks(conv.outputs)) * 4, 0.0f);
    std::copy(conv.bias.begin(), conv.bias.end(), bias.begin());
    return {.name = conv.name,
            .weights = uploadFloats(device, conv.name + ".weight", packRdaeConvWeights(conv, inputA)),
            .bias = uploadFloats(device, conv.name + ".bias", bias),
            .inputA = inputA,
            .inputB = conv.inputs - inputA,
            .outputs = conv.outputs};
}

RdaeTensor addRdaeConvPass(NodeContext& ctx, const std::string& name, const RdaeConvInputs& inputs,
                           const RdaeConvWeights& weights, RdaeActivation activation, const RdaeTensorFormat& format) {
    const auto& a = inputs.a;
    const auto& b = inputs.b;
    check(a.channels == weights.inputA, name, "input a has " + std::to_string(a.channels) + " channels, weights '" +
                                                  weights.name + "' take " + std::to_string(weights.inputA));
    check((b.valid() ? b.channels : 0) == weights.inputB, name,
          "input b has " + std::to_string(b.valid() ? b.channels : 0) + " channels, weights '" + weights.name +
              "' take " + std::to_string(weights.inputB));
    check(!b.valid() || b.level == a.level, name, "inputs a and b are at different levels");

    const uint32_t blockGroup = blocksPerInvocation(weights.outputs);
    const rhi::ComputePipeline pipeline =
        ctx.pipelines.get(detail::rdaeShader("conv", format), {{"blocksPerInvocation", double(blockGroup)}});
    rhi::PushConstants params(pipeline);
    const auto la = a.layout(), lb = rdaeTensorLayout(weights.inputB), lo = rdaeTensorLayout(weights.outputs);
    params.set("blocksA", la.blocks).set("tilesA", la.tilesX);
    params.set("blocksB", weights.inputB ? lb.blocks : 0u).set("tilesB", lb.tilesX);
    params.set("outBlocks", lo.blocks).set("tilesOut", lo.tilesX).set("outTileCount", lo.tilesX * lo.tilesY);
    params.set("leaky", uint32_t(activation));
    const auto size = params.slot("size", rhi::ScalarType::Int32, 2);
    const auto hasB = params.slot("hasB", rhi::ScalarType::Uint32);
    // Enough groups of output blocks to cover every tile of the grid (conv.glsl zeroes
    // the tiles past the last block).
    const uint32_t level = a.level, levels = format.levels,
                   groups = (lo.tilesX * lo.tilesY + blockGroup - 1) / blockGroup;
    const bool bIsHistory = inputs.bIsHistory, bPresent = b.valid();
    struct Out {
        graph::TextureHandle features;
    };
    const auto out = ctx.graph.addPass<Out>(name, [&](graph::PassBuilder& builder, Out& o) {
        builder.sample("input_a", a.texture);
        builder.sample("input_b", b.texture, {.optional = true});
        o.features = builder.write("features", builder.create(name, rdaeTensorInfo(weights.outputs, level, format)));
        const auto group = builder.bindGroup(pipeline, 0, {{.name = "weights", .buffer = weights.weights},
                                                            {.name = "bias", .buffer = weights.bias}});
        return [=](graph::PassContext& pc) mutable {
            const auto extent = rdaeLevelSize(pc.outputSize(), level, levels);
            const int32_t sizeValues[2] = {int32_t(extent.width), int32_t(extent.height)};
            params.set(size, std::span<const int32_t>(sizeValues));
            params.set(hasB, bPresent && (!bIsHistory || pc.historyValid()) ? 1u : 0u);
            // conv.glsl computes kPixels adjacent pixels per invocation.
            pc.dispatch(pipeline, group, {(extent.width + kPixels - 1) / kPixels, extent.height}, groups, params);
        };
    });
    return {out.features, weights.outputs, level};
}

} // namespace hush::passes
