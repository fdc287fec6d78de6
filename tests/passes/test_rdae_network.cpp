// The whole RDAE as graph passes: its architecture (the paper's 36 convolutions, ~3.2 M
// parameters), the GPU network against the CPU reference network over frames (the
// recurrence carries state; a reset clears it), and against PyTorch's unrolled
// forward of the same weights on the committed golden pairs (tests/passes/data,
// written by samples/rdae_training/export.py).
#include <catch2/catch.hpp>

#include <filesystem>
#include <map>

#include <hush/core/read_file.hpp>
#include <hush/passes/rdae/builtin_weights.hpp>
#include <hush/passes/rdae/network.hpp>

#include "rdae_test_util.hpp"
#include "reference/rdae_network.hpp"

using namespace hush;
using namespace hush::passes_test;

namespace {

passes::RdaeWeights readWeights(const std::filesystem::path& file) { return passes::RdaeWeights::read(file); }

Tensor frameOf(const std::vector<float>& values, uint32_t frame, uint32_t channels, uint32_t w, uint32_t h) {
    Tensor t(channels, w, h);
    std::copy_n(values.begin() + ptrdiff_t(size_t(frame) * t.values.size()), t.values.size(), t.values.begin());
    return t;
}

// Runs `frames` through the network in hush; returns each frame's output.
std::vector<Tensor> runNetwork(const passes::RdaeWeights& weights, const passes::RdaeArchitecture& a,
                               const std::vector<Tensor>& frames, rhi::Format format, bool resetBeforeLast = false) {
    const passes::RdaeTensorFormat f{.levels = a.levels, .format = format};
    const passes::RdaeNetwork network(test::gpu().device, weights, a);
    const uint32_t w = frames[0].width, h = frames[0].height;
    NodeHarness harness({w, h});
    Tensor input8(8, w, h);   // the input tensor's block padding channel stays 0
    auto fill = [&](const Tensor& x) {
        std::copy(x.values.begin(), x.values.end(), input8.values.begin());
        return packTensor(input8);
    };
    const passes::RdaeTensor input{harness.input("input", fill(frames[0]), format), 7, 0};
    const auto out = passes::addRdaeNetwork(harness.ctx, "rdae", input, network, f);
    std::vector<Tensor> outputs;
    for (size_t i = 0; i < frames.size(); ++i) {
        if (resetBeforeLast && i + 1 == frames.size()) harness.graph.resetHistory();
        harness.update("input", fill(frames[i]));
        outputs.push_back(runTensor(harness, out, w, h));
    }
    return outputs;
}

std::map<std::string, passes::RdaeConvParameters> parameters(const passes::RdaeWeights& w,
                                                             const passes::RdaeArchitecture& a) {
    std::map<std::string, passes::RdaeConvParameters> out;
    for (const auto& shape : a.convolutions()) out[shape.name] = passes::readRdaeConv(w, shape);
    return out;
}

const std::filesystem::path kData = HUSH_PASSES_TEST_DATA_DIR;

} // namespace

TEST_CASE("rdae architecture: the paper's 36 convolutions and about 3.2 M parameters", "[rdae][rdae-network]") {
    const passes::RdaeArchitecture paper{.width = 32, .levels = 6};
    CHECK(paper.convolutions().size() == 36);
    CHECK(paper.parameterCount() == 3121364);   // "3.2 million" (Sec. 5.3); docs/passes/rdae.md
    CHECK(paper.features(1) == 43);
    CHECK(paper.features(6) == 180);
    const passes::RdaeArchitecture narrow{.width = 16, .levels = 6};
    CHECK(narrow.parameterCount() == 777286);
    CHECK(narrow.multiplyAddsPerPixel() < paper.multiplyAddsPerPixel() / 3.5);
}

TEST_CASE("rdae network matches the CPU network over frames, and its state matters", "[rdae][rdae-network]") {
    test::ValidationScope scope;
    const passes::RdaeArchitecture a{.width = 4, .levels = 2};
    const auto weights = readWeights(kData / "rdae_random_w4_l2.safetensors");
    std::vector<Tensor> frames;
    for (uint32_t i = 0; i < 3; ++i) frames.push_back(randomTensor(7, 20, 12, -1.0f, 1.0f, 40 + i));
    const auto gpu = runNetwork(weights, a, frames, rhi::Format::RGBA32Float);
    reference::RdaeNetwork cpu(a, parameters(weights, a));
    for (size_t i = 0; i < frames.size(); ++i) {
        INFO("frame " << i);
        HUSH_REQUIRE_TENSORS_MATCH(gpu[i], cpu.forward(frames[i]), 1e-4f, 1e-4f);
    }
    const auto reset = runNetwork(weights, a, frames, rhi::Format::RGBA32Float, true);
    cpu.reset();
    HUSH_REQUIRE_TENSORS_MATCH(reset.back(), cpu.forward(frames.back()), 1e-4f, 1e-4f);
    CHECK(!compareTensors(reset.back(), gpu.back(), 1e-3f, 0.0f).empty());   // with history != without
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}

TEST_CASE("rdae network equals PyTorch's unrolled forward on the golden pairs", "[rdae][rdae-network][golden]") {
    test::ValidationScope scope;
    size_t pairs = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kData)) {
        const auto path = entry.path();
        if (path.string().find(".golden.safetensors") == std::string::npos) continue;
        const auto golden = readWeights(path);
        const passes::RdaeArchitecture a{.width = uint32_t(std::stoul(*golden.metadata("width"))),
                                         .levels = uint32_t(std::stoul(*golden.metadata("levels")))};
        // The weights beside the pair (a random model), else the ones hush ships.
        const auto besides = std::filesystem::path(path.string().substr(0, path.string().size() - 19) + ".safetensors");
        std::optional<passes::RdaeWeights> weights;
        if (std::filesystem::exists(besides)) weights = readWeights(besides);
        else if (const auto builtin = passes::findRdaeBuiltinWeights(a))
            weights = passes::RdaeWeights::parse(builtin->bytes, builtin->name);
        INFO(path.filename().string());
        REQUIRE(weights);
        // input [T, 7, H, W], output [T, 3, H, W]
        const auto shape = golden.shape("input");
        REQUIRE(shape.size() == 4);
        const uint32_t frames = uint32_t(shape[0]), h = uint32_t(shape[2]), w = uint32_t(shape[3]);
        const auto input = golden.tensor("input", {frames, 7, h, w});
        const auto output = golden.tensor("output", {frames, 3, h, w});
        std::vector<Tensor> in;
        for (uint32_t t = 0; t < frames; ++t) in.push_back(frameOf(input, t, 7, w, h));
        for (const auto format : {rhi::Format::RGBA32Float, rhi::Format::RGBA16Float}) {
            const auto gpu = runNetwork(*weights, a, in, format);
            // fp32 storage: summation order only. fp16: every activation rounded to 11 bits.
            const float tol = format == rhi::Format::RGBA32Float ? 2e-4f : 2e-2f;
            for (uint32_t t = 0; t < frames; ++t) {
                INFO(rhi::toString(format) << ", frame " << t);
                HUSH_REQUIRE_TENSORS_MATCH(gpu[t], frameOf(output, t, 3, w, h), tol, tol);
            }
        }
        ++pairs;
    }
    CHECK(pairs >= 1);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
