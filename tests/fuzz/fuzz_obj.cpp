// libFuzzer harness for the OBJ parser (scripts/fuzz.sh builds and runs it). Any
// input must parse or throw hush::Error; a parse must give self-consistent meshes.
#include <cstddef>
#include <cstdint>

#include "fuzz_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace hush::tracer;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    std::vector<Material> materials{Material{.name = "preset"}};
    ObjOptions options;
    options.maxVertices = 100'000;   // the limit path is reachable from small inputs too
    options.maxTriangles = 100'000;
    try {
        const std::vector<Mesh> meshes = parseObj(text, "fuzz.obj", materials, options, hush::fuzz::memoryReader(text));
        for (const Mesh& m : meshes) {
            hush::fuzz::require(!m.triangles.empty() && m.material < materials.size());
            hush::fuzz::require(m.normals.empty() || m.normals.size() == m.positions.size());
            for (const auto& t : m.triangles)
                hush::fuzz::require(t.x < m.positions.size() && t.y < m.positions.size() && t.z < m.positions.size());
        }
    } catch (const hush::Error&) {
    }
    return 0;
}
