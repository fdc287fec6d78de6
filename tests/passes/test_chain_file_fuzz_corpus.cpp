// Replays the kept fuzz corpora of chain files and the RDAE weights reader (grown by
// scripts/fuzz.sh) through the harnesses themselves (tests/fuzz/): every input
// parses or throws hush::Error. regress_* files once crashed or hung a reader.
#include <catch2/catch.hpp>

#include "../fuzz/fuzz_replay.hpp"

namespace {

void replay(const char* target, int (*harness)(const std::uint8_t*, std::size_t)) {
    hush::fuzz::replayCorpus(std::string(HUSH_PASSES_TEST_DATA_DIR "/fuzz_corpus/") + target, harness);
}

} // namespace

TEST_CASE("chain files: every fuzz corpus input parses or throws hush::Error (chain_file)", "[chain-file][fuzz]") {
    replay("chain_file", hush::fuzz::chainFile);
}

TEST_CASE("rdae weights: every fuzz corpus input parses or throws hush::Error (rdae_weights)", "[rdae][fuzz]") {
    replay("rdae_weights", hush::fuzz::rdaeWeights);
}
