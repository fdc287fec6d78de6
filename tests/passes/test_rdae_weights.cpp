// Reading network weights (safetensors layout): values in F32 and F16, and every way a
// file can be wrong gives an error naming the file and the tensor, never a crash.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include <hush/core/error.hpp>
#include <hush/passes/rdae/network.hpp>
#include <hush/passes/rdae/weights.hpp>

#include "rdae_test_util.hpp"

using namespace hush;
using namespace hush::passes_test;

namespace {

passes::RdaeWeights parse(const std::string& bytes) {
    return passes::RdaeWeights::parse(std::as_bytes(std::span(bytes.data(), bytes.size())), "w.safetensors");
}

std::string withHeader(const std::string& header, const std::string& data) {
    std::string bytes(8, '\0');
    for (int i = 0; i < 8; ++i) bytes[size_t(i)] = char((uint64_t(header.size()) >> (8 * i)) & 0xFF);
    return bytes + header + data;
}

} // namespace

TEST_CASE("rdae weights: F32 and F16 tensors read back exactly, with metadata", "[rdae][rdae-weights]") {
    const auto w = parse(safetensorsBytes({{"a.weight", {{2, 3}, {1, -2, 3.5f, 0, 1e-3f, 7}}}}, {{"width", "32"}}));
    CHECK(w.tensor("a.weight", {2, 3}) == std::vector<float>{1, -2, 3.5f, 0, 1e-3f, 7});
    CHECK(w.metadata("width") == "32");
    CHECK(!w.metadata("levels"));
    // 1.0, -2.0, 65504 and the smallest subnormal in binary16.
    const std::string halves("\x00\x3c\x00\xc0\xff\x7b\x01\x00", 8);
    const auto h = parse(withHeader(R"({"b":{"dtype":"F16","shape":[4],"data_offsets":[0,8]}})", halves));
    CHECK(h.tensor("b", {4}) == std::vector<float>{1.0f, -2.0f, 65504.0f, std::ldexp(1.0f, -24)});
}

TEST_CASE("rdae weights: a bad file names itself and the tensor", "[rdae][rdae-weights]") {
    const auto good = safetensorsBytes({{"a.weight", {{2, 2}, {1, 2, 3, 4}}}});
    CHECK_THROWS_WITH(parse("abc"), Catch::Contains("w.safetensors") && Catch::Contains("truncated"));
    CHECK_THROWS_WITH(parse(good.substr(0, 20)), Catch::Contains("truncated"));
    CHECK_THROWS_WITH(parse(good.substr(0, good.size() - 4)),
                      Catch::Contains("truncated") && Catch::Contains("a.weight"));
    CHECK_THROWS_WITH(parse(withHeader("{not json", "")), Catch::Contains("w.safetensors") && Catch::Contains("syntax"));
    CHECK_THROWS_WITH(parse(withHeader(R"({"a":{"dtype":"I8","shape":[1],"data_offsets":[0,1]}})", "x")),
                      Catch::Contains("'a'") && Catch::Contains("I8"));
    CHECK_THROWS_WITH(parse(withHeader(R"({"a":{"dtype":"F32","shape":[2],"data_offsets":[0,4]}})", "xxxx")),
                      Catch::Contains("'a'") && Catch::Contains("data_offsets"));
    CHECK_THROWS_WITH(parse(withHeader(R"({"a":{"dtype":"F32","shape":[1],"data_offsets":[0,4],"x":1}})", "xxxx")),
                      Catch::Contains("x"));
    const auto w = parse(good);
    CHECK_THROWS_WITH(w.tensor("b.weight", {2, 2}), Catch::Contains("no tensor 'b.weight'"));
    CHECK_THROWS_WITH(w.tensor("a.weight", {4}), Catch::Contains("'a.weight' has shape [2, 2]") && Catch::Contains("[4]"));
    const auto nan = parse(safetensorsBytes({{"c", {{2}, {1.0f, std::numeric_limits<float>::quiet_NaN()}}}}));
    CHECK_THROWS_WITH(nan.tensor("c", {2}), Catch::Contains("'c'") && Catch::Contains("non-finite") &&
                                                Catch::Contains("element 1"));
}

TEST_CASE("rdae weights: a missing file, a folder, and another network's metadata", "[rdae][rdae-weights]") {
    CHECK_THROWS_WITH(passes::RdaeWeights::read("/nonexistent/w.safetensors"),
                      Catch::Contains("/nonexistent/w.safetensors") && Catch::Contains("no such file"));
    CHECK_THROWS_WITH(passes::RdaeWeights::read(std::filesystem::temp_directory_path()),
                      Catch::Contains("not a regular file"));
    const auto w = parse(safetensorsBytes({}, {{"width", "16"}, {"levels", "6"}}));
    CHECK_THROWS_WITH(passes::checkRdaeMetadata(w, {.width = 32, .levels = 6}),
                      Catch::Contains("'width' is 16") && Catch::Contains("asks for 32"));
    CHECK_NOTHROW(passes::checkRdaeMetadata(w, {.width = 16, .levels = 6}));
}
