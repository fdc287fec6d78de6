// passes/common/atrous_lattice: the dispatch size of a level on the a-trous lattice
// covers every pixel exactly once, for any size and step (steps beyond the image
// included). The block's pixels are derived here as shaders/common/atrous_lattice.glsl
// derives them (latticeOrigin, latticeCentre), so a change to either that breaks
// the cover fails this test; the GPU side is compared pixel by pixel in
// test_eaw_atrous.cpp.
#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

#include <hush/passes/common/atrous_lattice.hpp>

using hush::rhi::Extent2D;

namespace {

// Pixels of invocation i along one axis: as latticeOrigin() + centre offset (2 * step)
// + b * step for the block's b-th pixel.
int64_t blockPixel(int64_t i, int64_t step, int64_t block, int64_t b) {
    const int64_t cell = i / step;
    return cell * block * step + (i - cell * step) + b * step;
}

// How often each pixel of an axis of `extent` pixels is filtered.
std::vector<int> axisCover(uint32_t extent, uint32_t threads, uint32_t step, uint32_t block) {
    std::vector<int> hits(extent, 0);
    for (uint32_t i = 0; i < threads; ++i)
        for (uint32_t b = 0; b < block; ++b) {
            const int64_t p = blockPixel(i, step, block, b);
            if (p < int64_t(extent)) ++hits[size_t(p)];
        }
    return hits;
}

} // namespace

TEST_CASE("a-trous lattice: every pixel is filtered exactly once", "[atrous-lattice]") {
    for (uint32_t block : {1u, 2u, 3u, 4u, 5u})   // 4: svgf.atrous's rows, eaw.atrous's blocks
        for (uint32_t extent : {1u, 2u, 3u, 5u, 7u, 8u, 17u, 64u, 131u, 257u})
            for (uint32_t step : {1u, 2u, 4u, 8u, 16u, 64u, 256u, 65536u}) {
                const Extent2D threads = hush::passes::atrousThreads({extent, 3}, step, block);
                INFO("block " << block << ", extent " << extent << ", step " << step << ": " << threads.width
                              << " threads");
                CHECK(threads.width <= extent);
                const auto hits = axisCover(extent, threads.width, step, block);
                for (uint32_t p = 0; p < extent; ++p) {
                    INFO("pixel " << p);
                    REQUIRE(hits[p] == 1);
                }
            }
}

TEST_CASE("a-trous lattice: a 2x2 block quarters the invocations where the step allows", "[atrous-lattice]") {
    CHECK(hush::passes::atrousThreads({1280, 720}, 1, 2).width == 640);
    CHECK(hush::passes::atrousThreads({1280, 720}, 8, 2).height == 360);
    // 720 rows at step 16: 22.5 cells of 32 rows, so 23 cells of 16 invocations.
    CHECK(hush::passes::atrousThreads({1280, 720}, 16, 2).height == 368);
    CHECK(hush::passes::atrousThreads({1280, 720}, 4, 1).width == 1280);
    // 100 pixels at step 16: cells of 32 pixels, the last one rounded up.
    CHECK(hush::passes::atrousThreads({100, 1}, 16, 2).width == 64);
    // A step beyond the image: one pixel per invocation, none outside.
    CHECK(hush::passes::atrousThreads({5, 3}, 64, 2).width == 5);
    CHECK(hush::passes::atrousThreads({0, 0}, 1, 2).width == 0);
}
