// The RDAE's 3x3 convolution against a double-precision CPU convolution: partial
// channel blocks, a concatenated second input, more output blocks than one invocation
// computes, odd sizes, linear and leaky, rgba32f and rgba16f storage; and the errors
// of a mismatched tensor.
#include <catch2/catch.hpp>

#include <hush/passes/rdae/conv.hpp>

#include "rdae_test_util.hpp"
#include "reference/rdae_conv.hpp"
#include "support/half.hpp"

using namespace hush;
using namespace hush::passes_test;

namespace {

const passes::RdaeTensorFormat kFp32{.levels = 0, .format = rhi::Format::RGBA32Float};
const passes::RdaeTensorFormat kFp16{.levels = 0, .format = rhi::Format::RGBA16Float};

Tensor roundedToHalf(Tensor t) {
    for (auto& v : t.values) v = test::halfToFloat(test::floatToHalf(v));
    return t;
}

struct Case {
    uint32_t width, height, inputA, inputB, outputs;
    bool leaky;
};

Tensor gpuConv(const Case& c, const Tensor& a, const Tensor* b, const passes::RdaeConvParameters& p,
               const passes::RdaeTensorFormat& format) {
    NodeHarness h({c.width, c.height});
    const auto weights = passes::uploadRdaeConv(test::gpu().device, p, c.inputA);
    passes::RdaeConvInputs in{.a = importTensor(h, "a", a, 0, format)};
    if (b) in.b = importTensor(h, "b", *b, 0, format);
    const auto out = passes::addRdaeConvPass(h.ctx, "conv", in, weights,
                                             c.leaky ? passes::RdaeActivation::LeakyRelu : passes::RdaeActivation::Linear,
                                             format);
    return runTensor(h, out, c.width, c.height);
}

} // namespace

TEST_CASE("rdae conv matches the CPU convolution (fp32 storage)", "[rdae][rdae-conv]") {
    test::ValidationScope scope;
    for (const Case c : {Case{1, 1, 3, 0, 5, true}, Case{37, 29, 7, 0, 16, true}, Case{13, 11, 13, 6, 9, true},
                         Case{16, 8, 8, 0, 17, false}, Case{9, 5, 43, 32, 3, false}}) {
        INFO(c.width << "x" << c.height << ", " << c.inputA << " + " << c.inputB << " -> " << c.outputs);
        const auto a = randomTensor(c.inputA, c.width, c.height, -1.0f, 1.0f, c.inputA * 7 + c.width);
        const auto b = randomTensor(c.inputB, c.width, c.height, -1.0f, 1.0f, c.inputB * 11 + 3);
        const auto p = randomConv("conv", c.inputA + c.inputB, c.outputs, c.outputs * 5 + c.height);
        const auto ref = reference::rdaeConv(a, c.inputB ? &b : nullptr, p, c.leaky);
        HUSH_REQUIRE_TENSORS_MATCH(gpuConv(c, a, c.inputB ? &b : nullptr, p, kFp32), ref, 1e-5f, 1e-5f);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("rdae conv in fp16 storage matches within half precision", "[rdae][rdae-conv]") {
    test::ValidationScope scope;
    const Case c{21, 17, 10, 5, 12, true};
    // The inputs as the rgba16f texture holds them; the output rounds once more.
    const auto a = roundedToHalf(randomTensor(c.inputA, c.width, c.height, -1.0f, 1.0f, 5));
    const auto b = roundedToHalf(randomTensor(c.inputB, c.width, c.height, -1.0f, 1.0f, 6));
    const auto p = randomConv("conv", c.inputA + c.inputB, c.outputs, 7);
    HUSH_REQUIRE_TENSORS_MATCH(gpuConv(c, a, &b, p, kFp16), reference::rdaeConv(a, &b, p, true), 1e-4f, 1e-3f);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("rdae conv names the pass and the weights when a tensor does not fit", "[rdae][rdae-conv]") {
    test::ValidationScope scope;
    NodeHarness h({8, 8});
    const auto weights = passes::uploadRdaeConv(test::gpu().device, randomConv("encoders.0.conv", 7, 8, 1), 7);
    const auto a = importTensor(h, "a", randomTensor(5, 8, 8, 0.0f, 1.0f, 2), 0, kFp32);
    REQUIRE_THROWS_WITH(passes::addRdaeConvPass(h.ctx, "rdae.encoders.0.conv", {.a = a}, weights,
                                                passes::RdaeActivation::LeakyRelu, kFp32),
                        Catch::Contains("rdae.encoders.0.conv") && Catch::Contains("5 channels") &&
                            Catch::Contains("'encoders.0.conv' take 7"));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
