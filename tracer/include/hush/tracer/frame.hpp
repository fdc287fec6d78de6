#pragma once
// A frame: the channels the tracer rendered for one image of a sequence, plus the
// camera that saw it. docs/frame-format.md is the on-disk contract (OpenEXR).
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include <hush/tracer/image.hpp>

namespace hush::tracer {

// The channels of DESIGN.md ("tracer and the frame format").
enum class Channel : uint8_t {
    Color,        // 1-spp noisy radiance (direct + indirect + emission)
    Direct,       // its direct-light part
    Indirect,     // its indirect part
    Matte,        // Mara mode: 1-path matte indirect, F and m factored out (seed 000 Eq. 9)
    Glossy,       // Mara mode: 1-path glossy indirect, F factored out (seed 000 Eq. 10)
    Albedo,       // primary hit's diffuse reflectance
    Specular,     // primary hit's specular colour F0
    Normal,       // world-space unit shading normal
    Position,     // world-space position
    Depth,        // positive linear view-space distance along the view axis
    Motion,       // previous-frame pixel position minus current, in pixels
    Roughness,    // GGX alpha
    MeshId,       // which mesh the primary ray hit (kNoMesh: none)
    VirtualPos,   // reflected virtual position for glossy reprojection (seed 000 Sec. 3.4)
    Reference,    // many-sample estimate of Color
    Emission,     // radiance emitted by the primary hit towards the camera (part of Direct)
};

inline constexpr Channel kAllChannels[] = {
    Channel::Color,  Channel::Direct,   Channel::Indirect, Channel::Matte,     Channel::Glossy,
    Channel::Albedo, Channel::Specular, Channel::Normal,   Channel::Position,  Channel::Depth,
    Channel::Motion, Channel::Roughness, Channel::MeshId,  Channel::VirtualPos, Channel::Reference,
    Channel::Emission,
};

enum class PixelKind : uint8_t { Half, Float, Uint };

// In memory every channel is float. MeshId holds the mesh index as a float (exact
// below 2^24) and kNoMesh where the primary ray hit nothing; on disk it is UINT with
// 0xFFFFFFFF for kNoMesh.
inline constexpr float kNoMesh = -1.0f;
inline constexpr uint32_t kNoMeshOnDisk = 0xFFFFFFFFu;

struct ChannelInfo {
    std::string_view name;                  // the EXR layer name: "color"
    uint32_t components = 3;
    std::array<std::string_view, 4> componentNames;   // EXR channel suffixes: "R", "G", "B"
    PixelKind storedAs = PixelKind::Half;   // how hush writes it by default
};

const ChannelInfo& channelInfo(Channel channel);
std::optional<Channel> parseChannel(std::string_view name);
// Parses "color,albedo,normal" (or "all"); throws hush::Error naming the unknown one.
std::vector<Channel> parseChannelList(std::string_view list);

struct CameraInfo {
    glm::mat4 view{1.0f};         // world -> view (camera looks down -Z)
    glm::mat4 projection{1.0f};   // view -> clip (Vulkan-style depth 0..1, y down in NDC)
    // The primary ray of pixel (x, y) passes through (x + 0.5 + jitter.x, y + 0.5 +
    // jitter.y); the projection matrix itself carries no jitter.
    glm::vec2 jitter{0.0f};
    glm::vec3 position{0.0f};
    float verticalFovDegrees = 45.0f;
    float nearPlane = 0.1f;
    float farPlane = 1000.0f;
};

struct Frame {
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t index = 0;            // position in the sequence
    std::string scene;             // which scene made it
    uint32_t referenceSpp = 0;     // samples per pixel of Reference, if present
    // Metres per world unit (Scene::sceneScale): what chains with thresholds in metres
    // (Mara et al.'s 5 cm / 7 cm) scale by. 1 when a renderer does not say.
    float metresPerUnit = 1.0f;
    CameraInfo camera;
    CameraInfo previousCamera;     // last frame's camera (equal to camera on frame 0)
    std::map<Channel, Image> channels;

    bool has(Channel c) const { return channels.count(c) != 0; }
    const Image& get(Channel c) const;   // throws hush::Error naming the missing channel
    Image& add(Channel c);               // allocates width x height x components, zeroed
};

} // namespace hush::tracer
