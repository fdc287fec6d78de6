#pragma once
// The tests' own compute shaders (tests/shaders/*.comp), compiled to SPIR-V at build
// time by hush_add_shader_library(hush_test_shaders ...) in tests/CMakeLists.txt.
// That function generates the definitions; these are the declarations.
#include <cstdint>
#include <span>
#include <string_view>

#include <hush/rhi/shader_library.hpp>

namespace hush::test_shaders {

// Every embedded shader, named by its path under tests/shaders/ without ".comp".
std::span<const hush::rhi::EmbeddedShader> all();
// The SPIR-V of one shader; throws hush::Error (NotFound) listing the names if absent.
std::span<const uint32_t> find(std::string_view name);

} // namespace hush::test_shaders
