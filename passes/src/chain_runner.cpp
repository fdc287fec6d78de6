#include <hush/passes/chain_runner.hpp>

#include <algorithm>
#include <cstring>

#include <hush/passes/chain_front_end.hpp>

#include <hush/core/error.hpp>
#include <hush/core/half.hpp>

namespace hush::passes {

namespace {
// The chain's inputs, and those of its optional inputs the frames carry.
std::vector<InputChannel> channelsToRead(const Chain& chain, const std::vector<InputChannel>& available) {
    std::vector<InputChannel> optional;
    for (auto c : chain.optionalInputs())
        if (available.empty() || std::find(available.begin(), available.end(), c) != available.end())
            optional.push_back(c);
    return mergeChannels(chain.inputs(), optional);
}

graph::RenderGraphDesc labelled(graph::RenderGraphDesc desc, const Chain& chain) {
    if (desc.label == graph::RenderGraphDesc{}.label) desc.label = chain.name();
    return desc;
}
} // namespace

ChainRunner::ChainRunner(rhi::Device device, std::unique_ptr<Chain> chain, rhi::Extent2D size,
                         const graph::RenderGraphDesc& desc, const std::vector<InputChannel>& available)
    : device_(device),
      chain_(std::move(chain)),
      pipelines_(device),
      graph_(device, labelled(desc, *chain_)),
      inputs_(device, size, channelsToRead(*chain_, available)) {
    graph_.setOutputSize(size);
    NodeContext ctx{graph_, pipelines_};
    outputs_ = chain_->build(ctx, inputs_.import(graph_));
    graph_.compile();
}

void ChainRunner::run() {
    graph_.execute();
    graph_.waitIdle();
}

std::vector<float> ChainRunner::readTexture(graph::TextureHandle h) const {
    const auto& texture = graph_.outputTexture(h);
    const auto format = texture.format();
    if (format != rhi::Format::RGBA32Float && format != rhi::Format::RGBA16Float)
        throw Error(ErrorKind::InvalidArgument, "chain '" + chain_->name() + "': output '" + texture.label() +
                                                    "' is " + std::string(rhi::toString(format)) +
                                                    ", not rgba32float or rgba16float");
    auto bytes = device_.queue().readTexture({.texture = texture, .state = graph_.outputState(h)});
    if (format == rhi::Format::RGBA32Float) {
        std::vector<float> values(bytes.size() / sizeof(float));
        std::memcpy(values.data(), bytes.data(), values.size() * sizeof(float));
        return values;
    }
    std::vector<float> values(bytes.size() / sizeof(uint16_t));
    for (size_t i = 0; i < values.size(); ++i) {
        uint16_t bits;
        std::memcpy(&bits, bytes.data() + 2 * i, 2);
        values[i] = core::halfToFloat(bits);
    }
    return values;
}

std::vector<float> ChainRunner::readDisplay() const { return readTexture(outputs_.display); }
std::vector<float> ChainRunner::readRadiance() const { return readTexture(outputs_.radiance); }

std::array<uint32_t, kInputChannelCount> ChainRunner::sanitizedCounts() const {
    std::array<uint32_t, kInputChannelCount> counts{};
    if (!outputs_.sanitizeCounts.valid()) return counts;
    auto bytes = device_.queue().readBuffer(graph_.outputBuffer(outputs_.sanitizeCounts));
    std::memcpy(counts.data(), bytes.data(), std::min(bytes.size(), sizeof counts));
    return counts;
}

} // namespace hush::passes
