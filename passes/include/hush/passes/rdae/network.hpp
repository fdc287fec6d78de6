#pragma once
// The whole recurrent denoising autoencoder as graph passes (architecture.hpp), one
// pass per convolution, pooling and upsampling, named "<name>.<convolution>" after
// the weights file ("rdae.encoders.0.rcnn.mix", "rdae.decoders.3.conv1", ...).
#include <map>
#include <memory>
#include <string>

#include <hush/passes/node_context.hpp>
#include <hush/passes/rdae/architecture.hpp>
#include <hush/passes/rdae/conv.hpp>
#include <hush/passes/rdae/weights.hpp>

namespace hush::passes {

// A network's weights, checked against its architecture and uploaded.
class RdaeNetwork {
public:
    // Reads every convolution's weight and bias from `weights`; throws hush::Error
    // naming the tensor on a missing one, a wrong shape or a non-finite value, and on
    // metadata that says another architecture.
    RdaeNetwork(const rhi::Device& device, const RdaeWeights& weights, const RdaeArchitecture& architecture);

    const RdaeArchitecture& architecture() const { return architecture_; }
    const RdaeConvWeights& conv(const std::string& name) const;

private:
    RdaeArchitecture architecture_;
    std::map<std::string, RdaeConvWeights> convs_;
};

// A convolution's parameters as read from the weights (shared with tests and tools).
RdaeConvParameters readRdaeConv(const RdaeWeights& weights, const RdaeConvShape& shape);
// Throws unless the weights' metadata (width, levels, features) matches `architecture`.
void checkRdaeMetadata(const RdaeWeights& weights, const RdaeArchitecture& architecture);

// Adds the network's passes; `input` is the input tensor (input.hpp). Returns the
// final layer's 3 channels at level 0.
RdaeTensor addRdaeNetwork(NodeContext& ctx, const std::string& name, const RdaeTensor& input,
                          const RdaeNetwork& network, const RdaeTensorFormat& format);

} // namespace hush::passes
