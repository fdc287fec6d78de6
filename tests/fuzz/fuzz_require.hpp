#pragma once

namespace hush::fuzz {

// A broken invariant in a reader's output: crash so that libFuzzer keeps the input.
inline void require(bool ok) {
    if (!ok) __builtin_trap();
}

} // namespace hush::fuzz
