#include <hush/core/error.hpp>
#include <hush/rhi/shader_library.hpp>

#include <string>

namespace hush::rhi {

std::span<const uint32_t> findEmbeddedShader(std::span<const EmbeddedShader> shaders, std::string_view name,
                                             std::string_view libraryName) {
    for (const auto& shader : shaders)
        if (shader.name == name) return shader.spirv;
    std::string known;
    for (const auto& shader : shaders) {
        if (!known.empty()) known += ", ";
        known += shader.name;
    }
    throw Error(ErrorKind::NotFound, "shader '" + std::string(name) + "' is not embedded in " +
                                         std::string(libraryName) + "; it has: " + (known.empty() ? "none" : known) +
                                         ". Shader names are paths under shaders/ without '.comp'.");
}

} // namespace hush::rhi
