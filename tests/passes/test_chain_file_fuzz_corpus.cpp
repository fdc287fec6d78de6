// Replays the kept fuzz corpora of chain files and the RDAE weights reader (grown by
// scripts/fuzz.sh) through the harnesses themselves (tests/fuzz/): every input
// parses or throws hush::Error. regress_* files once crashed or hung a reader.
#include <catch2/catch.hpp>

#include "../fuzz/fuzz_replay.hpp"

TEST_CASE("chain files: every fuzz corpus input parses or throws hush::Error (chain_file)", "[chain-file][fuzz]") {
    hush::fuzz::replayCorpus(HUSH_PASSES_TEST_DATA_DIR "/fuzz_corpus/chain_file", hush::fuzz::chainFile);
}

TEST_CASE("rdae weights: every fuzz corpus input parses or throws hush::Error (rdae_weights)", "[rdae][fuzz]") {
    hush::fuzz::replayCorpus(HUSH_PASSES_TEST_DATA_DIR "/fuzz_corpus/rdae_weights", hush::fuzz::rdaeWeights);
}
