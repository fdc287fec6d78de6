#pragma once
// hush's built-in compute shaders, embedded at build time (cmake/HushShaders.cmake).
#include <cstdint>
#include <span>
#include <string_view>

#include <hush/rhi/shader_library.hpp>

namespace hush::shaders {

// Every embedded shader, named by its path under shaders/ without ".comp".
std::span<const hush::rhi::EmbeddedShader> all();
// The SPIR-V of one shader; throws hush::Error (NotFound) listing the names.
std::span<const uint32_t> find(std::string_view name);

} // namespace hush::shaders
