#pragma once
// What the RDAE node tests share: tensors on the CPU (channel-major, like PyTorch's
// [C, H, W]), packed into and out of hush's tiled tensor textures
// (passes/rdae/tensor.hpp), random convolution parameters, and safetensors bytes
// made in the test (the toolkit's Python writer is not available to C++ tests).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <hush/passes/rdae/conv.hpp>
#include <hush/passes/rdae/tensor.hpp>

#include "pass_test_util.hpp"

namespace hush::passes_test {

struct Tensor {
    uint32_t channels = 0, width = 0, height = 0;
    std::vector<float> values;   // [channel][y][x]

    Tensor() = default;
    Tensor(uint32_t c, uint32_t w, uint32_t h, float fill = 0.0f)
        : channels(c), width(w), height(h), values(size_t(c) * w * h, fill) {}
    float& at(uint32_t c, uint32_t x, uint32_t y) { return values[(size_t(c) * height + y) * width + x]; }
    float at(uint32_t c, uint32_t x, uint32_t y) const { return values[(size_t(c) * height + y) * width + x]; }
};

Tensor randomTensor(uint32_t channels, uint32_t width, uint32_t height, float lo, float hi, uint64_t seed);
// The tiled texture image of a tensor, and back (rdae/tensor.hpp's layout).
FloatImage packTensor(const Tensor& t);
Tensor unpackTensor(const FloatImage& texture, uint32_t channels, uint32_t width, uint32_t height);

// A tensor uploaded and imported into the harness's graph at `level`.
passes::RdaeTensor importTensor(NodeHarness& h, const std::string& name, const Tensor& t, uint32_t level,
                                const passes::RdaeTensorFormat& format);
// Marks the tensor as output, runs one frame and reads it back.
Tensor runTensor(NodeHarness& h, const passes::RdaeTensor& t, uint32_t width, uint32_t height);

passes::RdaeConvParameters randomConv(const std::string& name, uint32_t inputs, uint32_t outputs, uint64_t seed);

// A safetensors file's bytes: F32 tensors with shapes, and metadata.
struct NamedTensor {
    std::vector<uint64_t> shape;
    std::vector<float> values;
};
std::string safetensorsBytes(const std::map<std::string, NamedTensor>& tensors,
                             const std::map<std::string, std::string>& metadata = {});

// |a - b| <= absTol + relTol |b| everywhere; "" or a message naming the worst element.
std::string compareTensors(const Tensor& gpu, const Tensor& reference, float absTol, float relTol);
#define HUSH_REQUIRE_TENSORS_MATCH(gpu, ref, absTol, relTol)                                            \
    do {                                                                                               \
        const std::string hush_diff_ = ::hush::passes_test::compareTensors((gpu), (ref), (absTol), (relTol)); \
        INFO(hush_diff_);                                                                              \
        REQUIRE(hush_diff_.empty());                                                                   \
    } while (false)

} // namespace hush::passes_test
