#pragma once
// The network weights hush ships (passes/weights/rdae_w<width>_l<levels>.safetensors,
// trained by samples/rdae_training; the command that made each is in
// docs/passes/rdae.md), compiled into the library so that nothing is looked up on
// disk at run time.
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <hush/passes/rdae/architecture.hpp>

namespace hush::passes {

struct RdaeBuiltinWeights {
    std::string name;                    // "rdae_w32_l6"
    RdaeArchitecture architecture;
    std::span<const std::byte> bytes;    // the safetensors file
};

std::vector<RdaeBuiltinWeights> rdaeBuiltinWeights();
std::optional<RdaeBuiltinWeights> findRdaeBuiltinWeights(const RdaeArchitecture& architecture);

} // namespace hush::passes
