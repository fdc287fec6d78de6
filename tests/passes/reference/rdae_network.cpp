#include "rdae_network.hpp"

#include "rdae_conv.hpp"
#include "rdae_pool.hpp"
#include "rdae_upsample.hpp"

namespace hush::passes_test::reference {

Tensor RdaeNetwork::conv(const std::string& name, const Tensor& a, const Tensor* b, bool leaky) const {
    return rdaeConv(a, b, convs_.at(name), leaky);
}

Tensor RdaeNetwork::forward(const Tensor& input) {
    std::vector<Tensor> skips;
    Tensor x = input;
    for (uint32_t k = 0; k < a_.levels; ++k) {
        const std::string stage = "encoders." + std::to_string(k);
        x = conv(stage + ".conv", x);
        Tensor in = conv(stage + ".rcnn.input", x);
        const Tensor zero(in.channels, in.width, in.height);
        const Tensor& previous = hidden_.size() > k ? hidden_[k] : zero;
        x = conv(stage + ".rcnn.output", conv(stage + ".rcnn.mix", in, &previous));
        skips.push_back(x);
        x = rdaePool(x);
    }
    hidden_ = skips;
    x = conv("bottleneck", x);
    for (uint32_t k = a_.levels - 1; k >= 1; --k) {
        const std::string stage = "decoders." + std::to_string(k);
        x = conv(stage + ".conv2", conv(stage + ".conv1", rdaeUpsample(x), &skips[k]));
    }
    return conv("final", rdaeUpsample(x), &skips[0], false);
}

} // namespace hush::passes_test::reference
