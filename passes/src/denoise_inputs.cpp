#include <hush/passes/denoise_inputs.hpp>

namespace hush::passes {

namespace {
using rhi::Format;
constexpr InputChannelInfo kChannels[kInputChannelCount] = {
    {InputChannel::Color, "color", Format::RGBA32Float, 3},
    {InputChannel::Direct, "direct", Format::RGBA32Float, 3},
    {InputChannel::Indirect, "indirect", Format::RGBA32Float, 3},
    {InputChannel::Albedo, "albedo", Format::RGBA32Float, 3},
    {InputChannel::Specular, "specular", Format::RGBA32Float, 3},
    {InputChannel::Normal, "normal", Format::RGBA32Float, 3},
    {InputChannel::Position, "position", Format::RGBA32Float, 3},
    {InputChannel::Depth, "depth", Format::R32Float, 1},
    {InputChannel::Motion, "motion", Format::RG32Float, 2},
    {InputChannel::Roughness, "roughness", Format::R32Float, 1},
    {InputChannel::MeshId, "meshid", Format::R32Float, 1},
    {InputChannel::Emission, "emission", Format::RGBA32Float, 3},
    {InputChannel::Matte, "matte", Format::RGBA32Float, 3},
    {InputChannel::Glossy, "glossy", Format::RGBA32Float, 3},
    {InputChannel::VirtualPos, "virtualpos", Format::RGBA32Float, 3},
};
} // namespace

const InputChannelInfo& inputChannelInfo(InputChannel channel) { return kChannels[size_t(channel)]; }
std::span<const InputChannelInfo> allInputChannels() { return kChannels; }

std::optional<InputChannel> parseInputChannel(std::string_view name) {
    for (const auto& c : kChannels)
        if (c.name == name) return c.channel;
    return std::nullopt;
}

} // namespace hush::passes
