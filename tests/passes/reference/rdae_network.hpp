#pragma once
// CPU reference of the whole recurrent denoising autoencoder (architecture.hpp), built
// from the reference convolution, pooling and upsampling, with the RCNN blocks'
// hidden states kept between frames as in PyTorch's unrolled forward.
#include <map>
#include <vector>

#include <hush/passes/rdae/architecture.hpp>
#include <hush/passes/rdae/conv.hpp>

#include "rdae_test_util.hpp"

namespace hush::passes_test::reference {

class RdaeNetwork {
public:
    RdaeNetwork(const passes::RdaeArchitecture& a, std::map<std::string, passes::RdaeConvParameters> convs)
        : a_(a), convs_(std::move(convs)) {}
    // One frame: 7 channels at a multiple of 2^levels in, 3 channels out.
    Tensor forward(const Tensor& input);
    void reset() { hidden_.clear(); }

private:
    Tensor conv(const std::string& name, const Tensor& a, const Tensor* b = nullptr, bool leaky = true) const;
    passes::RdaeArchitecture a_;
    std::map<std::string, passes::RdaeConvParameters> convs_;
    std::vector<Tensor> hidden_;
};

} // namespace hush::passes_test::reference
