#include <hush/passes/rdae/network.hpp>

#include <hush/core/error.hpp>
#include <hush/passes/rdae/pool.hpp>
#include <hush/passes/rdae/recurrent_block.hpp>
#include <hush/passes/rdae/upsample.hpp>

namespace hush::passes {

namespace {

std::string featureList(const RdaeArchitecture& a) {
    std::string s;
    for (uint32_t k = 0; k <= a.levels; ++k) s += (k ? "," : "") + std::to_string(a.features(k));
    return s;
}

} // namespace

void checkRdaeMetadata(const RdaeWeights& weights, const RdaeArchitecture& architecture) {
    auto expect = [&](const std::string& key, const std::string& value) {
        const auto found = weights.metadata(key);
        if (found && *found != value)
            throw Error(ErrorKind::InvalidArgument, weights.source() + ": metadata '" + key + "' is " + *found +
                                                        ", the network asks for " + value);
    };
    expect("width", std::to_string(architecture.width));
    expect("levels", std::to_string(architecture.levels));
    expect("features", featureList(architecture));
}

RdaeConvParameters readRdaeConv(const RdaeWeights& weights, const RdaeConvShape& shape) {
    RdaeConvParameters p{.name = shape.name, .inputs = shape.inputA + shape.inputB, .outputs = shape.outputs};
    p.weight = weights.tensor(shape.name + ".weight", {shape.outputs, p.inputs, 3, 3});
    p.bias = weights.tensor(shape.name + ".bias", {shape.outputs});
    return p;
}

RdaeNetwork::RdaeNetwork(const rhi::Device& device, const RdaeWeights& weights, const RdaeArchitecture& architecture)
    : architecture_(architecture) {
    architecture_.validate();
    checkRdaeMetadata(weights, architecture_);
    for (const auto& shape : architecture_.convolutions())
        convs_.emplace(shape.name, uploadRdaeConv(device, readRdaeConv(weights, shape), shape.inputA));
}

const RdaeConvWeights& RdaeNetwork::conv(const std::string& name) const {
    const auto it = convs_.find(name);
    if (it == convs_.end()) throw Error(ErrorKind::NotFound, "rdae network has no convolution '" + name + "'");
    return it->second;
}

RdaeTensor addRdaeNetwork(NodeContext& ctx, const std::string& name, const RdaeTensor& input,
                          const RdaeNetwork& network, const RdaeTensorFormat& format) {
    const auto& a = network.architecture();
    if (format.levels != a.levels)
        throw Error(ErrorKind::InvalidArgument, "rdae network '" + name + "': tensors pad for " +
                                                    std::to_string(format.levels) + " levels, the network has " +
                                                    std::to_string(a.levels));
    const auto leaky = RdaeActivation::LeakyRelu;
    auto conv = [&](const std::string& n, RdaeConvInputs in, RdaeActivation act = RdaeActivation::LeakyRelu) {
        return addRdaeConvPass(ctx, name + "." + n, in, network.conv(n), act, format);
    };
    std::vector<RdaeTensor> skips;
    RdaeTensor x = input;
    for (uint32_t k = 0; k < a.levels; ++k) {
        const std::string stage = "encoders." + std::to_string(k);
        x = conv(stage + ".conv", {.a = x}, leaky);
        x = addRdaeRecurrentBlock(ctx, name + "." + stage + ".rcnn", x,
                                  {&network.conv(stage + ".rcnn.input"), &network.conv(stage + ".rcnn.mix"),
                                   &network.conv(stage + ".rcnn.output")},
                                  format);
        skips.push_back(x);
        x = addRdaePoolPass(ctx, name + "." + stage + ".pool", x, format);
    }
    x = conv("bottleneck", {.a = x});
    for (uint32_t k = a.levels - 1; k >= 1; --k) {
        const std::string stage = "decoders." + std::to_string(k);
        x = addRdaeUpsamplePass(ctx, name + "." + stage + ".upsample", x, format);
        x = conv(stage + ".conv1", {.a = x, .b = skips[k]});
        x = conv(stage + ".conv2", {.a = x});
    }
    x = addRdaeUpsamplePass(ctx, name + ".final.upsample", x, format);
    return conv("final", {.a = x, .b = skips[0]}, RdaeActivation::Linear);
}

} // namespace hush::passes
