// Buffers sized from the output size (BufferInfo::sizeFromOutput): compile evaluates
// the function for the current output size, and a size change resizes the buffer.
#include <catch2/catch.hpp>

#include "graph/graph_test_util.hpp"

using namespace hush;
using namespace hush::graph;

TEST_CASE("a buffer sized from the output size follows it across recompiles", "[graph][buffer-size]") {
    test::ValidationScope scope;
    RenderGraph g(test::gpu().device);
    g.setOutputSize({16, 8});
    BufferHandle out;
    g.addPass("per-pixel", [&](PassBuilder& b) {
        BufferInfo info;
        info.sizeFromOutput = [](rhi::Extent2D e) { return uint64_t(e.width) * e.height * 12; };
        out = b.write("data", b.create("per-pixel.data", info));
        return [](PassContext&) {};
    });
    g.markOutput(out);
    g.compile();
    CHECK(g.outputBuffer(out).size() == 16u * 8u * 12u);
    CHECK_THAT(g.dumpJson(), Catch::Contains("\"bytes\": 1536"));
    g.setOutputSize({33, 5});
    CHECK(g.needsCompile());
    g.compile();
    CHECK(g.outputBuffer(out).size() == 33u * 5u * 12u);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(scope);
}
