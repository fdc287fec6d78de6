// Replays the kept fuzz corpora of the EXR frame reader and the BMFR dataset reader
// (grown by scripts/fuzz.sh) through the harnesses themselves (tests/fuzz/): every
// input reads or throws hush::Error. regress_* files once crashed or hung a reader.
#include <catch2/catch.hpp>

#include "../fuzz/fuzz_replay.hpp"

namespace {

void replay(const char* target, int (*harness)(const std::uint8_t*, std::size_t)) {
    hush::fuzz::replayCorpus(std::string(HUSH_TEST_DATA_DIR "/fuzz_corpus/") + target, harness);
}

} // namespace

TEST_CASE("frame files: every fuzz corpus input reads or throws hush::Error (exr_frame)", "[frame-io][fuzz]") {
    replay("exr_frame", hush::fuzz::exrFrame);
}

TEST_CASE("frame files: every fuzz corpus input reads or throws hush::Error (bmfr_dataset)", "[frame-io][bmfr][fuzz]") {
    replay("bmfr_dataset", hush::fuzz::bmfrDataset);
}
