#include <hush/core/error.hpp>
#include <hush/tracer/frame.hpp>

namespace hush::tracer {

const ChannelInfo& channelInfo(Channel channel) {
    // Colours are half (HDR radiance fits fp16's range for display-referred work and
    // halves the files); geometry that reprojection compares is float.
    static const ChannelInfo kInfo[] = {
        {"color", 3, {"R", "G", "B"}, PixelKind::Half},
        {"direct", 3, {"R", "G", "B"}, PixelKind::Half},
        {"indirect", 3, {"R", "G", "B"}, PixelKind::Half},
        {"matte", 3, {"R", "G", "B"}, PixelKind::Half},
        {"glossy", 3, {"R", "G", "B"}, PixelKind::Half},
        {"albedo", 3, {"R", "G", "B"}, PixelKind::Half},
        {"specular", 3, {"R", "G", "B"}, PixelKind::Half},
        {"normal", 3, {"X", "Y", "Z"}, PixelKind::Float},
        {"position", 3, {"X", "Y", "Z"}, PixelKind::Float},
        {"depth", 1, {"Z"}, PixelKind::Float},
        {"motion", 2, {"X", "Y"}, PixelKind::Float},
        {"roughness", 1, {"Y"}, PixelKind::Half},
        {"meshid", 1, {"ID"}, PixelKind::Uint},
        {"virtualpos", 3, {"X", "Y", "Z"}, PixelKind::Float},
        {"reference", 3, {"R", "G", "B"}, PixelKind::Float},
        {"emission", 3, {"R", "G", "B"}, PixelKind::Half},
    };
    return kInfo[size_t(channel)];
}

std::optional<Channel> parseChannel(std::string_view name) {
    for (Channel c : kAllChannels)
        if (channelInfo(c).name == name) return c;
    return std::nullopt;
}

std::vector<Channel> parseChannelList(std::string_view list) {
    if (list == "all") return {std::begin(kAllChannels), std::end(kAllChannels)};
    std::vector<Channel> out;
    size_t start = 0;
    while (start <= list.size()) {
        const size_t comma = std::min(list.find(',', start), list.size());
        const std::string_view name = list.substr(start, comma - start);
        if (!name.empty()) {
            const auto channel = parseChannel(name);
            if (!channel) {
                std::string known;
                for (Channel c : kAllChannels) known += std::string(known.empty() ? "" : ", ") + std::string(channelInfo(c).name);
                throw Error(ErrorKind::InvalidArgument,
                            "unknown channel '" + std::string(name) + "'; channels are: " + known + " (or 'all')");
            }
            bool seen = false;
            for (Channel c : out) seen |= c == *channel;
            if (!seen) out.push_back(*channel);
        }
        start = comma + 1;
    }
    return out;
}

const Image& Frame::get(Channel c) const {
    const auto it = channels.find(c);
    if (it == channels.end())
        throw Error(ErrorKind::NotFound, "frame " + std::to_string(index) + " has no channel '" +
                                             std::string(channelInfo(c).name) + "'");
    return it->second;
}

Image& Frame::add(Channel c) {
    auto& image = channels[c];
    image = Image(width, height, channelInfo(c).components);
    return image;
}

} // namespace hush::tracer
