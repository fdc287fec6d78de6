#pragma once
// What the C API's opaque handles hold.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <hush/passes/chain_runner.hpp>
#include <hush/passes/metrics/metrics_evaluator.hpp>
#include <hush/rhi/rhi.hpp>

struct HushContext_T {
    std::optional<hush::rhi::Instance> instance;   // none on an imported VkDevice
    hush::rhi::Device device;
    std::string adapterName;
    std::unique_ptr<hush::passes::MetricsEvaluator> metrics;   // for the last size compared
};

struct HushDenoiser_T {
    HushContext context = nullptr;
    std::unique_ptr<hush::passes::ChainRunner> runner;
    std::vector<hush::passes::InputChannel> inputs;   // what the chain reads, in the order listed
    std::array<bool, hush::passes::kInputChannelCount> set{};
    bool executed = false;
    std::vector<float> staging;   // a strided host image, packed
};

namespace hush::capi {

// The input named `name` of the denoiser, or hush::Error naming the argument and
// listing the inputs.
passes::InputChannel denoiserInput(const HushDenoiser_T& denoiser, const char* name);

} // namespace hush::capi
