#pragma once
// The harnesses of the readers of binary and chain files, callable without libFuzzer:
// the normal (g++) build compiles them with HUSH_FUZZ_REPLAY and the Catch2 "fuzz
// corpus" tests feed each one its kept corpus, so every input a fuzzer once kept,
// and every crash reproducer (regress_*), runs in every build. Each returns 0, or
// traps (require) on a broken invariant; anything thrown but hush::Error escapes.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace hush::fuzz {

int exrFrame(const std::uint8_t* data, std::size_t size);      // fuzz_exr_frame.cpp
int bmfrDataset(const std::uint8_t* data, std::size_t size);   // fuzz_bmfr_dataset.cpp
int chainFile(const std::uint8_t* data, std::size_t size);     // fuzz_chain_file.cpp
int rdaeWeights(const std::uint8_t* data, std::size_t size);   // fuzz_rdae_weights.cpp

// The files of a kept corpus, sorted by name.
inline std::vector<std::filesystem::path> corpusFiles(const std::filesystem::path& folder) {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        if (entry.is_regular_file()) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

inline std::vector<std::uint8_t> fileBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

} // namespace hush::fuzz

// libFuzzer's entry point calling `function`; nothing in the replay build, where the
// Catch2 tests call the function themselves.
#ifdef HUSH_FUZZ_REPLAY
#define HUSH_FUZZ_TARGET(function)
#else
#define HUSH_FUZZ_TARGET(function)                                                    \
    extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) { \
        return function(data, size);                                                  \
    }
#endif

#ifdef HUSH_FUZZ_REPLAY
#include <catch2/catch.hpp>

namespace hush::fuzz {

// Feeds every file of a kept corpus to `harness`: each must return 0 (a trap or an
// exception other than hush::Error fails the test).
inline void replayCorpus(const std::filesystem::path& folder, int (*harness)(const std::uint8_t*, std::size_t)) {
    const auto files = corpusFiles(folder);
    REQUIRE(files.size() >= 1);   // the seeds at least
    for (const auto& file : files) {
        INFO(file.string());
        const auto bytes = fileBytes(file);
        CHECK(harness(bytes.data(), bytes.size()) == 0);
    }
}

} // namespace hush::fuzz
#endif
