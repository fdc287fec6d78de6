#pragma once
// A frame's camera, as chains use it: the CPU side of the frame (the GPU side is the
// input textures). A node that needs it (Mara's compose: the view direction;
// its glossy temporal stage: last frame's view-projection; RDAE: view-space normals)
// keeps the shared pointer DenoiseInputs carries and writes what it needs into its
// push constants every frame, by name. Matrices are column-major (GLM's layout);
// world space is right-handed, +Y up, the camera looks down -Z (DESIGN.md).
#include <array>
#include <memory>

namespace hush::passes {

struct FrameCamera {
    using Matrix = std::array<float, 16>;
    static constexpr Matrix kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

    Matrix view = kIdentity;                 // world -> view
    Matrix projection = kIdentity;           // view -> clip (Vulkan depth 0..1, y down)
    Matrix previousView = kIdentity;         // last frame's camera (this one on frame 0)
    Matrix previousProjection = kIdentity;
    std::array<float, 3> position{};         // world space
    // Metres per world unit (the frame header's hush.metresPerUnit): thresholds given
    // in metres (Mara et al.'s 5 cm) are scaled by it.
    float metresPerUnit = 1.0f;
};

// a * b for column-major 4x4 matrices.
FrameCamera::Matrix multiply(const FrameCamera::Matrix& a, const FrameCamera::Matrix& b);
// Throws hush::Error (InvalidArgument) naming the field that is not finite, or a
// metresPerUnit that is not positive.
void validate(const FrameCamera& camera);

// Shared between the frame inputs (which set it before each frame) and the nodes
// that read it while recording.
using FrameCameraRef = std::shared_ptr<const FrameCamera>;

} // namespace hush::passes
