// Replays the kept fuzz corpora of the EXR frame reader and the BMFR dataset reader
// (grown by scripts/fuzz.sh) through the harnesses themselves (tests/fuzz/): every
// input reads or throws hush::Error. regress_* files once crashed or hung a reader.
#include <catch2/catch.hpp>

#include "../fuzz/fuzz_replay.hpp"

TEST_CASE("frame files: every fuzz corpus input reads or throws hush::Error (exr_frame)", "[frame-io][fuzz]") {
    hush::fuzz::replayCorpus(HUSH_TEST_DATA_DIR "/fuzz_corpus/exr_frame", hush::fuzz::exrFrame);
}

TEST_CASE("frame files: every fuzz corpus input reads or throws hush::Error (bmfr_dataset)", "[frame-io][bmfr][fuzz]") {
    hush::fuzz::replayCorpus(HUSH_TEST_DATA_DIR "/fuzz_corpus/bmfr_dataset", hush::fuzz::bmfrDataset);
}
