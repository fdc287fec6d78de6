#pragma once
// CPU reference of passes/common/surface: normalDepth (4 channels) and gradientMesh
// (4 channels), written from the packing and the depth gradient stated in the node
// header, independently of the shader. SurfaceImages is the packed surface every
// reference that reads one (reproject, SVGF) takes.
#include "pass_test_util.hpp"

namespace hush::passes_test::reference {

struct SurfaceImages {
    FloatImage normalDepth, gradientMesh;
};
SurfaceImages surface(const FloatImage& normal, const FloatImage& depth, const FloatImage& meshId);

} // namespace hush::passes_test::reference
