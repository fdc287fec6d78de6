#pragma once
// The recurrent denoising autoencoder's shape (Chaitanya et al. 2017, Sec. 4.1-4.2,
// Figs. 2 and 4; docs/passes/rdae.md, "Architecture"): a U-Net whose every encoder
// stage ends in a recurrent (RCNN) block, with `levels` poolings.
//   encoders.<k>  (k = 0 .. levels-1, at 1/2^k):  conv to f_k, RCNN block (3 convs,
//                 its hidden state kept across frames), then 2x2 max pooling
//   bottleneck    (at 1/2^levels): conv f_{levels-1} -> f_levels
//   decoders.<k>  (k = levels-1 .. 1): 2x2 upsampling, concatenation with encoder k's
//                 output, conv1 and conv2 to f_k
//   final         upsampling, concatenation with encoder 0's output, conv to RGB (linear)
// f_k = round(width (4/3)^k). With width 32 and 6 levels: 36 convolutions, 3.12 M
// parameters (the paper: 36 and "3.2 million").
#include <cstdint>
#include <string>
#include <vector>

namespace hush::passes {

// One convolution of the network: its name in the weights file and in the graph
// ("<chain>.<name>"), its level, and its input split (a, then b concatenated).
struct RdaeConvShape {
    std::string name;
    uint32_t level = 0;
    uint32_t inputA = 0;
    uint32_t inputB = 0;
    uint32_t outputs = 0;
    bool linear = false;   // the output layer; every other one is leaky ReLU 0.1
};

struct RdaeArchitecture {
    uint32_t width = 32;   // features of the first encoder stage
    uint32_t levels = 6;   // encoder stages, each ending in a pooling

    uint32_t features(uint32_t level) const;
    // Every convolution, in execution order.
    std::vector<RdaeConvShape> convolutions() const;
    uint64_t parameterCount() const;
    // Multiply-adds per pixel of the (padded) full-resolution frame.
    double multiplyAddsPerPixel() const;
    // Throws hush::Error (InvalidArgument) on a width or level count out of range.
    void validate() const;
};

inline constexpr uint32_t kRdaeOutputChannels = 3;

} // namespace hush::passes
