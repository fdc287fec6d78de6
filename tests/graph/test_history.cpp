// History: last frame's value of a transient, ping-ponged automatically. Invalid on
// the first frame and for one frame after resetHistory().
#include <catch2/catch.hpp>

#include <array>

#include "graph/graph_test_util.hpp"

using namespace hush;
using namespace hush::graph;
using namespace hush::graph_test;
using hush::test::gpu;
using hush::test::ValidationScope;

namespace {

constexpr uint32_t kW = 40, kH = 24;
constexpr uint32_t kMaxFrames = 16;
constexpr uint32_t kNothing = 0xFFFFFFFFu;   // what accumulate.comp writes to 'seen' without history

uint32_t addOf(uint64_t frame) { return uint32_t(frame) * 3u + 1u; }

// A graph whose pass 'accumulate' writes acc = (history valid ? last acc : 0) + input
// + addOf(frame), and seen = what it read of the history. Records what PassContext
// said about the history, frame by frame.
struct AccumulateGraph {
    Pipelines p = makePipelines();
    rhi::Texture input = makeTexture("input", kW, kH);
    RenderGraph g{gpu().device, {.label = "history"}};
    TextureHandle acc, seen;
    std::array<int, kMaxFrames> historyValid{};   // -1: pass not run in that frame

    AccumulateGraph() {
        historyValid.fill(-1);
        upload(input, fillImage(11, kW, kH), ResourceState::Undefined, ResourceState::StorageRead);
        g.setOutputSize({kW, kH});
        const auto in = g.importTexture(
            "input", input, {.initialState = ResourceState::StorageRead, .finalState = ResourceState::StorageRead});
        g.addPass("accumulate", [&](PassBuilder& b) {
            const auto sum = b.create("acc", {.format = kFormat});
            b.read("history", g.history(sum));
            b.read("current", in);
            acc = b.write("acc", sum);
            seen = b.write("seen", b.create("seen", {.format = kFormat}));
            const auto group = b.bindGroup(p.accumulate);
            return [this, group, pipeline = p.accumulate, params = rhi::PushConstants(p.accumulate)](
                       PassContext& ctx) mutable {
                const uint64_t frame = ctx.frameIndex();
                if (frame < kMaxFrames) historyValid[frame] = ctx.historyValid() ? 1 : 0;
                params.set("historyValid", ctx.historyValid()).set("add", addOf(frame));
                ctx.dispatch(pipeline, group, {kW, kH}, params);
            };
        });
        g.markOutput(acc);
        g.markOutput(seen);
    }
};

} // namespace

TEST_CASE("history: over 10 frames each frame reads the last one's value, and reset invalidates one frame",
          "[graph][history][gpu]") {
    ValidationScope validation;
    AccumulateGraph a;
    const auto in = fillImage(11, kW, kH);
    constexpr uint32_t kFrames = 10, kResetAt = 6;
    std::vector<uint32_t> previous;   // last frame's acc, as read back
    for (uint32_t f = 0; f < kFrames; ++f) {
        INFO("frame " << f);
        if (f == kResetAt) a.g.resetHistory();   // e.g. a camera cut
        a.g.execute();
        a.g.waitIdle();
        const bool valid = f != 0 && f != kResetAt;
        CHECK(a.historyValid[f] == (valid ? 1 : 0));

        const auto seen = readOutput(a.g, a.seen);
        const auto acc = readOutput(a.g, a.acc);
        std::vector<uint32_t> expectedSeen(in.size(), kNothing), expectedAcc(in.size());
        for (size_t i = 0; i < in.size(); ++i) {
            if (valid) expectedSeen[i] = previous[i];
            expectedAcc[i] = (valid ? previous[i] : 0u) + in[i] + addOf(f);
        }
        CHECK(seen == expectedSeen);   // the history read is exactly last frame's acc
        CHECK(acc == expectedAcc);
        previous = acc;
    }
    CHECK(a.g.compileCount() == 1);
    const auto memory = a.g.memory();
    CHECK(memory.historyBytes == 2 * uint64_t(kW) * kH * 4);   // acc and its history: one ping-pong pair
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("history: with frames in flight the ping-pong still hands each frame the last one", "[graph][history][gpu]") {
    ValidationScope validation;
    AccumulateGraph a;
    const auto in = fillImage(11, kW, kH);
    constexpr uint32_t kFrames = 9;
    for (uint32_t f = 0; f < kFrames; ++f) a.g.execute();   // no waiting between frames
    a.g.waitIdle();
    for (uint32_t f = 0; f < kFrames; ++f) CHECK(a.historyValid[f] == (f == 0 ? 0 : 1));

    // acc after n frames: sum over frames of (input + addOf(frame)); seen: the sum one frame shorter.
    std::vector<uint32_t> expectedAcc(in.size()), expectedSeen(in.size());
    for (size_t i = 0; i < in.size(); ++i) {
        uint32_t sum = 0;
        for (uint32_t f = 0; f < kFrames; ++f) {
            expectedSeen[i] = sum;
            sum += in[i] + addOf(f);
        }
        expectedAcc[i] = sum;
    }
    CHECK(readOutput(a.g, a.acc) == expectedAcc);
    CHECK(readOutput(a.g, a.seen) == expectedSeen);

    // A reset right after a recompile-free run: one invalid frame, then valid again.
    a.g.resetHistory();
    a.g.execute();
    a.g.execute();
    a.g.waitIdle();
    CHECK(a.historyValid[kFrames] == 0);
    CHECK(a.historyValid[kFrames + 1] == 1);
    std::vector<uint32_t> restarted(in.size());
    for (size_t i = 0; i < in.size(); ++i) restarted[i] = in[i] + addOf(kFrames) + in[i] + addOf(kFrames + 1);
    CHECK(readOutput(a.g, a.acc) == restarted);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("history: a recompile starts it over (invalid for one frame)", "[graph][history][gpu]") {
    ValidationScope validation;
    AccumulateGraph a;
    a.g.execute();
    a.g.execute();
    a.g.setOutputSize({kW / 2, kH / 2});   // new sizes: new textures, nothing to carry over
    a.g.execute();
    a.g.execute();
    a.g.waitIdle();
    CHECK(a.g.compileCount() == 2);
    CHECK(a.historyValid[0] == 0);
    CHECK(a.historyValid[1] == 1);
    CHECK(a.historyValid[2] == 0);
    CHECK(a.historyValid[3] == 1);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("history: declared before its source and bound to it later, a pass reads a later pass's last value",
          "[graph][history][gpu]") {
    ValidationScope validation;
    const auto p = makePipelines();
    RenderGraph g(gpu().device, {.label = "history.feedback"});
    g.setOutputSize({kW, kH});
    // "early" copies last frame's "late" (feedback); "late" = early + 5. Frame 0 reads an
    // invalid history (copy.comp reads it anyway: the first frame's value is whatever
    // the texture held), so only frames 1 and 2 are checked.
    const auto lastLate = g.history("late.history", {.format = kFormat});
    const auto early = addCopy(g, p, "early", lastLate, 0);
    const auto late = addCopy(g, p, "late", early, 5);
    g.bindHistory(lastLate, late);
    g.markOutput(late);
    CHECK(g.historySource(lastLate) == late);
    std::vector<uint32_t> previous;
    for (int frame = 0; frame < 3; ++frame) {
        g.execute();
        g.waitIdle();
        const auto now = readOutput(g, late, gpu().device);
        if (frame > 0)
            for (size_t i = 0; i < now.size(); ++i) REQUIRE(now[i] == previous[i] + 5);
        previous = now;
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("history: one history per texture, bound once, and only to a texture a pass creates", "[graph][history]") {
    const auto p = makePipelines();
    RenderGraph g(gpu().device, {.label = "history.binding"});
    const auto a = addFill(g, p, "a", 1);
    const auto b = addFill(g, p, "b", 2);
    const auto c = addFill(g, p, "c", 3);
    CHECK(g.history(a) == g.history(a));   // asking twice gives the same history
    const auto free = g.history("free", {.format = kFormat});
    CHECK_THROWS_WITH(g.bindHistory(free, a), Catch::Contains("'a' already has a history"));
    g.bindHistory(free, b);
    CHECK_THROWS_WITH(g.bindHistory(free, c), Catch::Contains("history 'free' is already bound to 'b'"));
    const auto imported = g.importTexture("imported", makeTexture("imported", 4, 4));
    CHECK_THROWS_WITH(g.history(imported), Catch::Contains("the source must be a texture a pass of graph"));
    CHECK(g.findTexture("b") == b);
    CHECK(g.findTexture("imported") == imported);
    CHECK_FALSE(g.findTexture("nothing").valid());
}
