#include <hush/passes/rdae/recurrent_block.hpp>

namespace hush::passes {

RdaeTensor addRdaeRecurrentBlock(NodeContext& ctx, const std::string& name, const RdaeTensor& input,
                                 const RdaeRecurrentWeights& weights, const RdaeTensorFormat& format) {
    const auto leaky = RdaeActivation::LeakyRelu;
    const RdaeTensor in = addRdaeConvPass(ctx, name + ".input", {.a = input}, *weights.input, leaky, format);
    // Declared before its source exists: the mix reads last frame's output of this block.
    const RdaeTensor hidden{ctx.graph.history(name + ".hidden", rdaeTensorInfo(weights.output->outputs, input.level, format)),
                            weights.output->outputs, input.level};
    const RdaeTensor mixed =
        addRdaeConvPass(ctx, name + ".mix", {.a = in, .b = hidden, .bIsHistory = true}, *weights.mix, leaky, format);
    const RdaeTensor out = addRdaeConvPass(ctx, name + ".output", {.a = mixed}, *weights.output, leaky, format);
    ctx.graph.bindHistory(hidden.texture, out.texture);
    return out;
}

} // namespace hush::passes
