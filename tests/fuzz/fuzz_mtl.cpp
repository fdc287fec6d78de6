// libFuzzer harness for the MTL parser (scripts/fuzz.sh builds and runs it). Any
// input must parse or throw hush::Error; parsed materials must be finite and valid.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "fuzz_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace hush::tracer;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        for (const Material& m : parseMtl(text, "fuzz.mtl")) {
            hush::fuzz::require(!m.name.empty() && std::isfinite(m.roughness) && m.roughness >= 0.0f);
            for (int c = 0; c < 3; ++c)
                hush::fuzz::require(std::isfinite(m.albedo[c]) && std::isfinite(m.specular[c]) &&
                                    std::isfinite(m.emission[c]) && m.emission[c] >= 0.0f);
        }
    } catch (const hush::Error&) {
    }
    return 0;
}
