// libFuzzer harness for the RDAE weights reader (passes/src/rdae/weights.cpp): any
// bytes must parse or throw hush::Error; every tensor of a parsed file must then
// read as floats of its own shape or throw hush::Error (a non-finite value).
#include <cstddef>
#include <cstdint>
#include <span>

#include <hush/core/error.hpp>
#include <hush/passes/rdae/weights.hpp>

#include "fuzz_replay.hpp"
#include "fuzz_require.hpp"

int hush::fuzz::rdaeWeights(const std::uint8_t* data, std::size_t size) {
    const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
    try {
        const auto weights = hush::passes::RdaeWeights::parse(bytes, "fuzz.safetensors");
        for (const std::string& name : weights.names()) {
            const auto& shape = weights.shape(name);
            std::uint64_t count = 1;
            for (const std::uint64_t extent : shape) count *= extent;
            try {
                hush::fuzz::require(weights.tensor(name, shape).size() == count);
            } catch (const hush::Error&) {
            }
        }
    } catch (const hush::Error&) {
    }
    return 0;
}

HUSH_FUZZ_TARGET(hush::fuzz::rdaeWeights)
