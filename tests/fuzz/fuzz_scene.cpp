// libFuzzer harness for the JSON scene parser (scripts/fuzz.sh builds and runs it).
// Any input must parse or throw hush::Error; a parsed scene has passed validate(),
// which is checked again here in case parseSceneFile ever stops calling it.
#include <cstddef>
#include <cstdint>

#include <hush/tracer/scene_file.hpp>

#include "fuzz_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    hush::tracer::Scene scene;
    try {
        scene = hush::tracer::parseSceneFile(text, "fuzz.json", hush::fuzz::memoryReader(text));
    } catch (const hush::Error&) {
        return 0;
    }
    try {
        scene.validate();
    } catch (...) {
        __builtin_trap();
    }
    return 0;
}
