// Blender Cycles multilayer OpenEXR files as hush frames (docs/blender.md). Cycles
// writes its passes as "<view layer>.<Pass>.<component>"; this maps them onto hush's
// layers with the conventions measured on Blender 3.4:
//   color     Combined.RGB
//   direct    DiffDir*DiffCol + GlossDir*GlossCol + TransDir*TransCol + Emit + Env
//   indirect  DiffInd*DiffCol + GlossInd*GlossCol + TransInd*TransCol
//   emission  Emit                      albedo    DiffCol (0 on metals: not demodulated)
//   normal    Normal, world, Z up -> Y up: (x, z, -y)
//   position  Position, likewise        depth     Depth.Z (1e10 on misses -> far)
//   motion    Vector.XY: previous minus current in pixels, y up -> (x, -y)
//   meshid    IndexOB where objects have pass indices, else 0 on every hit
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfInputFile.h>

#include <algorithm>
#include <array>
#include <map>
#include <optional>

#include "frame_io_detail.hpp"

namespace hush::tracer::detail {
namespace {

// Each hush layer, the Blender passes it is made of, and the setting that turns them on.
struct CyclesSource {
    Channel channel;
    const char* passes;    // for messages
    const char* setting;   // View Layer Properties > Passes > ...
};
constexpr CyclesSource kSources[] = {
    {Channel::Color, "Combined", "Data > Combined"},
    {Channel::Direct, "DiffDir, DiffCol, GlossDir, GlossCol", "Light > Diffuse and Glossy: Direct and Color"},
    {Channel::Indirect, "DiffInd, DiffCol, GlossInd, GlossCol", "Light > Diffuse and Glossy: Indirect and Color"},
    {Channel::Emission, "Emit", "Light > Emission"},
    {Channel::Albedo, "DiffCol", "Light > Diffuse: Color"},
    {Channel::Normal, "Normal", "Data > Normal"},
    {Channel::Position, "Position", "Data > Position"},
    {Channel::Depth, "Depth", "Data > Z"},
    {Channel::Motion, "Vector", "Data > Vector (with motion blur off)"},
    {Channel::MeshId, "Normal (and IndexOB)", "Data > Normal; Data > Indexes > Object Index for ids"},
};

// The file's passes: name -> component -> pixels.
using Passes = std::map<std::string, std::map<std::string, std::vector<float>>>;

Passes readPasses(Imf::InputFile& file, const std::string& viewLayer, const Imath::Box2i& window) {
    const size_t width = size_t(window.max.x - window.min.x + 1), height = size_t(window.max.y - window.min.y + 1);
    Passes passes;
    Imf::FrameBuffer buffer;
    const std::string prefix = viewLayer + ".";
    for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it) {
        const std::string name = it.name();
        if (name.rfind(prefix, 0) != 0) continue;
        const std::string rest = name.substr(prefix.size());
        const auto dot = rest.rfind('.');
        if (dot == std::string::npos) continue;
        auto& pixels = passes[rest.substr(0, dot)][rest.substr(dot + 1)];
        pixels.resize(width * height);
        buffer.insert(name, Imf::Slice::Make(Imf::FLOAT, pixels.data(), window, sizeof(float), sizeof(float) * width));
    }
    file.setFrameBuffer(buffer);
    file.readPixels(window.min.y, window.max.y);
    return passes;
}

const std::vector<float>* component(const Passes& passes, const std::string& pass, const std::string& c) {
    const auto p = passes.find(pass);
    if (p == passes.end()) return nullptr;
    const auto it = p->second.find(c);
    return it == p->second.end() ? nullptr : &it->second;
}

bool has(const Passes& passes, const std::string& pass, const char* components = "RGB") {
    for (const char* c = components; *c; ++c)
        if (!component(passes, pass, std::string(1, *c))) return false;
    return true;
}

// Sum over `terms` of light[i] * colour[i] (colour "" means 1), per RGB component;
// passes a file lacks (transmission on a scene without glass) add nothing.
void addProducts(const Passes& passes, std::initializer_list<std::array<const char*, 2>> terms, Image& out) {
    for (const auto& [light, colour] : terms) {
        if (!has(passes, light) || (*colour && !has(passes, colour))) continue;
        for (int c = 0; c < 3; ++c) {
            const std::string rgb(1, "RGB"[c]);
            const auto& l = *component(passes, light, rgb);
            const std::vector<float>* k = *colour ? component(passes, colour, rgb) : nullptr;
            for (size_t i = 0; i < l.size(); ++i) out.pixels[i * 3 + size_t(c)] += l[i] * (k ? (*k)[i] : 1.0f);
        }
    }
}

void copyVector(const Passes& passes, const std::string& pass, const char* components, bool zUp, Image& out) {
    std::array<const std::vector<float>*, 3> src{};
    for (size_t c = 0; components[c]; ++c) src[c] = component(passes, pass, std::string(1, components[c]));
    for (size_t i = 0; i < src[0]->size(); ++i) {
        float* texel = out.pixels.data() + i * out.channels;
        if (zUp) {   // Blender's world is Z up, hush's Y up: (x, y, z) -> (x, z, -y)
            texel[0] = (*src[0])[i], texel[1] = (*src[2])[i], texel[2] = -(*src[1])[i];
        } else {
            for (uint32_t c = 0; c < out.channels; ++c) texel[c] = (*src[c])[i];
        }
    }
}

// Whether the passes named by `has(pass, components)` make `channel`.
template <class Has> bool canMake(Has&& has, Channel channel) {
    switch (channel) {
    case Channel::Color: return has("Combined", "RGB");
    case Channel::Direct: return has("DiffDir", "RGB") && has("DiffCol", "RGB");
    case Channel::Indirect: return has("DiffInd", "RGB") && has("DiffCol", "RGB");
    case Channel::Emission: return has("Emit", "RGB");
    case Channel::Albedo: return has("DiffCol", "RGB");
    case Channel::Normal: return has("Normal", "XYZ");
    case Channel::Position: return has("Position", "XYZ");
    case Channel::Depth: return has("Depth", "Z");
    case Channel::Motion: return has("Vector", "XY");
    case Channel::MeshId: return has("Normal", "XYZ");
    default: return false;
    }
}

bool isHit(const Passes& p, size_t i) {
    return (*component(p, "Normal", "X"))[i] != 0.0f || (*component(p, "Normal", "Y"))[i] != 0.0f ||
           (*component(p, "Normal", "Z"))[i] != 0.0f;
}

void make(const Passes& p, Channel channel, Image& out) {
    switch (channel) {
    case Channel::Color: return copyVector(p, "Combined", "RGB", false, out);
    case Channel::Direct:
        return addProducts(p, {{"DiffDir", "DiffCol"}, {"GlossDir", "GlossCol"}, {"TransDir", "TransCol"}, {"Emit", ""}, {"Env", ""}}, out);
    case Channel::Indirect: return addProducts(p, {{"DiffInd", "DiffCol"}, {"GlossInd", "GlossCol"}, {"TransInd", "TransCol"}}, out);
    case Channel::Emission: return copyVector(p, "Emit", "RGB", false, out);
    case Channel::Albedo: return copyVector(p, "DiffCol", "RGB", false, out);
    case Channel::Normal: return copyVector(p, "Normal", "XYZ", true, out);
    case Channel::Position: return copyVector(p, "Position", "XYZ", true, out);
    case Channel::Depth: {
        const auto& z = *component(p, "Depth", "Z");
        float far = 1000.0f;   // misses (1e10 in Cycles) go to a far plane beyond every hit
        for (float v : z)
            if (v < 1e9f) far = std::max(far, 10.0f * v);
        for (size_t i = 0; i < z.size(); ++i) out.pixels[i] = z[i] < 1e9f ? z[i] : far;
        return;
    }
    case Channel::Motion: {
        const auto &x = *component(p, "Vector", "X"), &y = *component(p, "Vector", "Y");
        for (size_t i = 0; i < x.size(); ++i) out.pixels[2 * i] = x[i], out.pixels[2 * i + 1] = -y[i];   // y up -> down
        return;
    }
    case Channel::MeshId: {
        const std::vector<float>* index = component(p, "IndexOB", "X");
        const bool indexed = index && std::any_of(index->begin(), index->end(), [](float v) { return v != 0.0f; });
        for (size_t i = 0; i < out.pixels.size(); ++i)
            out.pixels[i] = !isHit(p, i) ? kNoMesh : indexed ? (*index)[i] : 0.0f;
        return;
    }
    default: return;
    }
}

} // namespace

std::string cyclesViewLayer(const Imf::Header& header) {
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
        const std::string name = it.name();
        const auto at = name.find(".Combined.R");
        if (at != std::string::npos && at > 0 && at + 11 == name.size()) return name.substr(0, at);
    }
    return {};
}

std::vector<Channel> cyclesLayers(const Imf::Header& header, const std::string& viewLayer) {
    const auto has = [&](const char* pass, const char* components) {
        for (const char* c = components; *c; ++c)
            if (!header.channels().findChannel(viewLayer + "." + pass + "." + std::string(1, *c))) return false;
        return true;
    };
    std::vector<Channel> layers;
    for (const CyclesSource& s : kSources)
        if (canMake(has, s.channel)) layers.push_back(s.channel);
    return layers;
}

Frame readCyclesFrame(Imf::InputFile& file, const std::string& viewLayer, Frame frame, const ReadOptions& options,
                      const std::string& path) {
    const Passes passes = readPasses(file, viewLayer, file.header().dataWindow());
    std::vector<Channel> wanted = options.channels;
    if (wanted.empty())
        for (const CyclesSource& s : kSources) wanted.push_back(s.channel);
    for (Channel channel : wanted) {
        if (canMake([&](const char* pass, const char* components) { return has(passes, pass, components); }, channel)) {
            make(passes, channel, frame.add(channel));
            continue;
        }
        if (!options.requireChannels || options.channels.empty()) continue;
        const auto source = std::find_if(std::begin(kSources), std::end(kSources), [&](const CyclesSource& s) { return s.channel == channel; });
        throw Error(ErrorKind::NotFound,
                    "cannot read frame '" + path + "': Blender Cycles file (view layer '" + viewLayer + "') without '" +
                        std::string(channelInfo(channel).name) + "'" +
                        (source == std::end(kSources)
                             ? std::string(": hush cannot make it from Cycles passes")
                             : std::string(": render the ") + source->passes + " pass(es) (View Layer Properties > Passes > " +
                                   source->setting + "; docs/blender.md)"));
    }
    return frame;
}

} // namespace hush::tracer::detail
