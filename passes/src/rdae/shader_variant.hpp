#pragma once
// The RDAE kernels come in two storage formats: "rdae/<kernel>" (rgba16f) and
// "rdae/<kernel>_rgba32f" (shaders/rdae/*.glsl, included by both).
#include <string>

#include <hush/passes/rdae/tensor.hpp>

namespace hush::passes::detail {

inline std::string rdaeShader(const std::string& kernel, const RdaeTensorFormat& format) {
    return "rdae/" + kernel + (format.format == rhi::Format::RGBA32Float ? "_rgba32f" : "");
}

} // namespace hush::passes::detail
