#pragma once
// SPIR-V embedded in a library by cmake/HushShaders.cmake, looked up by name.
#include <cstdint>
#include <span>
#include <string_view>

namespace hush::rhi {

struct EmbeddedShader {
    std::string_view name;              // "bench/copy_rgba16f": path under shaders/, no extension
    std::span<const uint32_t> spirv;
};

// Throws hush::Error (NotFound) listing the available names when `name` is absent.
std::span<const uint32_t> findEmbeddedShader(std::span<const EmbeddedShader> shaders,
                                             std::string_view name, std::string_view libraryName);

} // namespace hush::rhi
