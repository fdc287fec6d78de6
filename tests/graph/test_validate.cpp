// Compile step 1, validate: every error a user can make, with the message they get.
// Each error is checked on a GraphModel built by hand (validate() alone) and, where
// the builder can produce it, through RenderGraph::compile().
#include <catch2/catch.hpp>

#include <hush/graph/compile_steps.hpp>

#include "graph/graph_test_util.hpp"
#include "graph/model_builders.hpp"

using namespace hush;
using namespace hush::graph;
using namespace hush::graph_test;
using hush::test::gpu;
using hush::test::ValidationScope;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

// validate()'s message for `model`, "" when it passes.
std::string problems(const GraphModel& model) {
    return errorMessage([&] { validate(model); });
}

// A setup step for passes that only declare: their execute step does nothing.
ExecuteFn nothing() {
    return [](PassContext&) {};
}

// A pass "render" writing a fresh r32ui transient "noisy" of `size`.
TextureHandle addProducer(RenderGraph& g, SizeSpec size = SizeSpec::relative()) {
    TextureHandle out;
    g.addPass("render", [&](PassBuilder& b) {
        out = b.write("dst", b.create("noisy", {.format = kFormat, .size = size}));
        return nothing();
    });
    return out;
}

// A pass `name` reading `in` through port `port` with `spec`, writing an output.
void addConsumer(RenderGraph& g, const std::string& name, const std::string& port, TextureHandle in,
                 const InputSpec& spec = {}) {
    g.addPass(name, [&](PassBuilder& b) {
        b.read(port, in, spec);
        g.markOutput(b.write("dst", b.create(name + ".out", {.format = kFormat})));
        return nothing();
    });
}

std::string compileError(RenderGraph& g) {
    return errorMessage([&] { g.compile(); });
}

} // namespace

TEST_CASE("validate: a well-formed model passes, and the builder's graph compiles", "[graph][validate][gpu]") {
    ValidationScope validation;
    GraphModel m;
    m.resources = {textureDecl("in", ResourceOrigin::Imported, 1), textureDecl("t", ResourceOrigin::Transient, 2)};
    m.passes = {passDecl("p", {readOf(0, 0), writeOf(1, 0)})};
    m.resources[1].output = true;
    CHECK(problems(m).empty());

    RenderGraph g(gpu().device, {.label = "validate.ok"});
    g.setOutputSize({32, 24});
    addConsumer(g, "consumer", "color", addProducer(g));
    CHECK(compileError(g).empty());
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("validate: an unknown handle names the port, the pass and the handle", "[graph][validate][gpu]") {
    ValidationScope validation;
    const std::string expected =
        "input 'src' of pass 'blur' uses an unknown resource handle (#7): it does not come from this graph";
    GraphModel m;
    m.resources = {textureDecl("t", ResourceOrigin::Transient, 2)};
    m.passes = {passDecl("blur", {readOf(7, 0), writeOf(0, 0)})};
    CHECK_THAT(problems(m), Contains(expected));

    // Through the builder: a handle of another graph.
    RenderGraph other(gpu().device, {.label = "other"});
    for (int i = 0; i < 8; ++i) other.history("h" + std::to_string(i), {.format = kFormat});
    const TextureHandle foreign = other.history("foreign", {.format = kFormat});
    REQUIRE(foreign.index == 8);
    RenderGraph g(gpu().device, {.label = "validate.unknown"});
    addConsumer(g, "blur", "src", TextureHandle{7, 0});
    addConsumer(g, "sharpen", "src", foreign);
    const auto message = compileError(g);
    CHECK_THAT(message, Contains(expected));
    CHECK_THAT(message, Contains("input 'src' of pass 'sharpen' uses an unknown resource handle (#8)"));
    CHECK_THAT(message, StartsWith("render graph is invalid (2 problems):"));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("validate: a stale handle names the version and who wrote the newer one", "[graph][validate][gpu]") {
    ValidationScope validation;
    const std::string expected = "input 'src' of pass 'late' uses a stale handle: version 0 of 'color', but "
                                 "version 1 was already written by pass 'tonemap'; use the handle that write returned";
    GraphModel m;
    m.resources = {textureDecl("color", ResourceOrigin::Imported, 2), textureDecl("o", ResourceOrigin::Transient, 2)};
    auto stale = readOf(0, 0);
    stale.latestAtDeclaration = 1;
    m.passes = {passDecl("tonemap", {accessDecl("color", 0, 0, Access::StorageReadWrite)}),
                passDecl("late", {stale, writeOf(1, 0)})};
    CHECK_THAT(problems(m), Contains(expected));

    auto texture = makeTexture("color", 32, 32);
    RenderGraph g(gpu().device, {.label = "validate.stale"});
    const auto color = g.importTexture("color", texture);
    g.addPass("tonemap", [&](PassBuilder& b) {
        const auto next = b.readWrite("color", color);
        CHECK(next.version == 1);
        CHECK(next.index == color.index);
        return nothing();
    });
    addConsumer(g, "late", "src", color);   // version 0, after version 1 exists
    const auto message = compileError(g);
    CHECK_THAT(message, Contains(expected));
    CHECK_THAT(message, StartsWith("render graph is invalid (1 problem):"));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("validate: an unconnected required input is an error, an optional one is not", "[graph][validate][gpu]") {
    ValidationScope validation;
    const std::string expected = "input 'motion' of pass 'svgf.reproject' is not connected";
    GraphModel m;
    m.resources = {textureDecl("color", ResourceOrigin::Imported, 1), textureDecl("o", ResourceOrigin::Transient, 2)};
    auto motion = readOf(kNone, 0, "motion");
    m.passes = {passDecl("svgf.reproject", {readOf(0, 0, "color"), motion, writeOf(1, 0)})};
    CHECK_THAT(problems(m), Contains(expected));
    m.passes[0].accesses[1].optional = true;
    CHECK(problems(m).empty());

    RenderGraph g(gpu().device, {.label = "validate.unconnected"});
    g.setOutputSize({32, 32});
    addConsumer(g, "svgf.reproject", "motion", TextureHandle{});
    CHECK_THAT(compileError(g), Contains(expected));

    // Optional and unconnected: compiles and runs; the pass sees an invalid handle.
    const auto p = makePipelines();
    RenderGraph ok(gpu().device, {.label = "validate.optional"});
    ok.setOutputSize({32, 32});
    const auto source = addFill(ok, p, "source", 5);
    TextureHandle result;
    bool sawInvalid = false;
    ok.addPass("svgf.reproject", [&](PassBuilder& b) {
        const auto motionIn = b.read("motion", TextureHandle{}, {.optional = true});
        sawInvalid = !motionIn.valid();
        b.read("src", source);
        result = b.write("dst", b.create("reprojected", {.format = kFormat}));
        const auto group = b.bindGroup(p.copy);
        rhi::PushConstants params(p.copy);
        params.set("add", 1u);
        return [=, pipeline = p.copy](PassContext& ctx) { ctx.dispatch(pipeline, group, {32u, 32u}, params); };
    });
    ok.markOutput(result);
    CHECK(sawInvalid);
    REQUIRE(compileError(ok).empty());
    ok.execute();
    ok.waitIdle();
    const auto expectedValues = fillImage(5 + 1, 32, 32);
    CHECK(readOutput(ok, result) == expectedValues);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("validate: reading a resource nobody writes", "[graph][validate][gpu]") {
    ValidationScope validation;
    const std::string expected = "input 'src' of pass 'blur' reads 'orphan', which no pass writes before it";
    GraphModel m;
    m.resources = {textureDecl("orphan", ResourceOrigin::Transient, 1), textureDecl("o", ResourceOrigin::Transient, 2)};
    m.passes = {passDecl("blur", {readOf(0, 0), writeOf(1, 0)})};
    CHECK_THAT(problems(m), Contains(expected));

    RenderGraph g(gpu().device, {.label = "validate.unwritten"});
    TextureHandle orphan;
    g.addPass("declare", [&](PassBuilder& b) {
        orphan = b.create("orphan", {.format = kFormat});   // created, never written
        return nothing();
    });
    addConsumer(g, "blur", "src", orphan);
    CHECK_THAT(compileError(g), Contains(expected));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("validate: format mismatch between producer and consumer", "[graph][validate][gpu]") {
    ValidationScope validation;
    const std::string expected =
        "input 'color' of pass 'denoise' expects format rgba16float, but 'noisy' (written by pass 'render') is r32uint";
    GraphModel m;
    m.resources = {textureDecl("noisy", ResourceOrigin::Transient, 2), textureDecl("o", ResourceOrigin::Transient, 2)};
    auto read = readOf(0, 1, "color");
    read.expectFormat = rhi::Format::RGBA16Float;
    m.passes = {passDecl("render", {writeOf(0, 0)}), passDecl("denoise", {read, writeOf(1, 0)})};
    CHECK_THAT(problems(m), Contains(expected));
    m.passes[1].accesses[0].expectFormat = rhi::Format::R32Uint;
    CHECK(problems(m).empty());

    RenderGraph g(gpu().device, {.label = "validate.format"});
    const auto noisy = addProducer(g);
    addConsumer(g, "denoise", "color", noisy, {.format = rhi::Format::RGBA16Float});
    addConsumer(g, "fine", "color", noisy, {.format = rhi::Format::R32Uint});
    const auto message = compileError(g);
    CHECK_THAT(message, Contains(expected));
    CHECK_THAT(message, StartsWith("render graph is invalid (1 problem):"));   // 'fine' is fine
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("validate: extent mismatch, absolute and relative sizes resolved", "[graph][validate][gpu]") {
    ValidationScope validation;
    const std::string expected =
        "input 'color' of pass 'upsample' expects extent 16x16, but 'noisy' (written by pass 'render') is 32x24";
    GraphModel m;
    m.outputSize = {32, 24};
    m.resources = {textureDecl("noisy", ResourceOrigin::Transient, 2, kFormat, SizeSpec::relative()),
                   textureDecl("o", ResourceOrigin::Transient, 2)};
    auto read = readOf(0, 1, "color");
    read.expectSize = SizeSpec::absolute(16, 16);
    m.passes = {passDecl("render", {writeOf(0, 0)}), passDecl("upsample", {read, writeOf(1, 0)})};
    CHECK_THAT(problems(m), Contains(expected));
    m.passes[1].accesses[0].expectSize = SizeSpec::absolute(32, 24);   // the same extent, said differently
    CHECK(problems(m).empty());

    RenderGraph g(gpu().device, {.label = "validate.extent"});
    g.setOutputSize({32, 24});
    const auto noisy = addProducer(g);
    addConsumer(g, "upsample", "color", noisy, {.size = SizeSpec::absolute(16, 16)});
    addConsumer(g, "same", "color", noisy, {.size = SizeSpec::relative(1.0f)});
    CHECK_THAT(compileError(g), Contains(expected));

    RenderGraph half(gpu().device, {.label = "validate.extent.half"});
    half.setOutputSize({32, 24});
    const auto small = addProducer(half, SizeSpec::absolute(16, 12));
    addConsumer(half, "half", "color", small, {.size = SizeSpec::relative(0.5f)});
    CHECK(compileError(half).empty());
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("validate: two unordered writers of one version (hand-built model)", "[graph][validate]") {
    GraphModel m;
    m.resources = {textureDecl("accum", ResourceOrigin::Transient, 2)};
    m.resources[0].output = true;
    m.passes = {passDecl("left", {writeOf(0, 0)}), passDecl("right", {writeOf(0, 0)})};
    CHECK_THAT(problems(m), Contains("passes 'left' and 'right' both write version 0 of 'accum' with no order "
                                     "between them; chain the second write on the first's result"));
    // Chained, the same two writes are fine.
    m.resources[0].versionCount = 3;
    m.passes[1].accesses[0] = accessDecl("dst", 0, 1, Access::StorageReadWrite);
    CHECK(problems(m).empty());
}

TEST_CASE("validate: a cycle names its passes, and order() refuses it (hand-built model)", "[graph][validate]") {
    // A writes x from y's second version; B writes y from x's second version.
    GraphModel m;
    m.resources = {textureDecl("x", ResourceOrigin::Transient, 2), textureDecl("y", ResourceOrigin::Transient, 2)};
    m.resources[0].output = true;
    m.passes = {passDecl("A", {readOf(1, 1, "in"), writeOf(0, 0, "out")}),
                passDecl("B", {readOf(0, 1, "in"), writeOf(1, 0, "out")})};
    CHECK_THAT(problems(m), Contains("cycle between passes: 'A' -> 'B' -> 'A'"));
    CHECK_THAT(errorMessage([&] { order(m, allAlive(m)); }),
               Contains("render graph has a cycle: passes 'A', 'B' each wait for another of them"));
}

TEST_CASE("validate: history with no texture to come from", "[graph][validate][gpu]") {
    ValidationScope validation;
    const std::string expected =
        "history 'ghost' is read, but bound to no texture to come from";
    GraphModel m;
    m.resources = {textureDecl("ghost", ResourceOrigin::History, 1), textureDecl("o", ResourceOrigin::Transient, 2)};
    m.passes = {passDecl("temporal", {readOf(0, 0, "history"), writeOf(1, 0)})};
    CHECK_THAT(problems(m), Contains(expected));

    RenderGraph g(gpu().device, {.label = "validate.history"});
    addConsumer(g, "temporal", "history", g.history("ghost", {.format = kFormat}));
    CHECK_THAT(compileError(g), Contains(expected));

    // Writing a history is an error too: it is last frame's value, read-only.
    GraphModel w;
    w.resources = {textureDecl("acc", ResourceOrigin::History, 2), textureDecl("acc", ResourceOrigin::Transient, 2)};
    w.resources[0].historySource = 1;
    w.passes = {passDecl("bad", {writeOf(0, 0, "history")}), passDecl("acc", {writeOf(1, 0)})};
    CHECK_THAT(problems(w), Contains("output 'history' of pass 'bad' writes history 'acc', which is read-only"));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("validate: every problem of a graph is reported at once", "[graph][validate]") {
    GraphModel m;
    m.resources = {textureDecl("orphan", ResourceOrigin::Transient, 1), textureDecl("o", ResourceOrigin::Transient, 2)};
    m.passes = {passDecl("a", {readOf(0, 0), readOf(kNone, 0, "motion"), writeOf(1, 0)}),
                passDecl("a", {readOf(9, 0, "extra")})};
    const auto message = problems(m);
    CHECK_THAT(message, StartsWith("render graph is invalid (4 problems):"));
    CHECK_THAT(message, Contains("two passes are named 'a'; pass names must be unique"));
    CHECK_THAT(message, Contains("input 'src' of pass 'a' reads 'orphan', which no pass writes before it"));
    CHECK_THAT(message, Contains("input 'motion' of pass 'a' is not connected"));
    CHECK_THAT(message, Contains("input 'extra' of pass 'a' uses an unknown resource handle (#9)"));
}

TEST_CASE("validate: a shader binding with no port of its name, and a port no binding takes, fail at compile",
          "[graph][validate][gpu]") {
    ValidationScope validation;
    const auto p = makePipelines();
    {
        RenderGraph g(gpu().device, {.label = "validate.unbound"});
        g.setOutputSize({32, 32});
        const auto a = addFill(g, p, "a", 1);
        TextureHandle out;
        g.addPass("sneaky", [&](PassBuilder& builder) {
            builder.read("a", a);   // combine.comp also reads 'b', which this pass does not declare
            out = builder.write("dst", builder.create("sneaky.out", {.format = kFormat}));
            const auto group = builder.bindGroup(p.combine);
            return [=, pipeline = p.combine, params = combineParams(p.combine, {})](PassContext& ctx) {
                ctx.dispatch(pipeline, group, {32u, 32u}, params);
            };
        });
        g.markOutput(out);
        const auto error = test::errorFrom([&] { g.compile(); });
        REQUIRE(error);
        CHECK(error->kind() == ErrorKind::BindingMismatch);
        CHECK_THAT(error->what(), Contains("pass 'sneaky': binding 'b' (set 0, binding 1) of shader") &&
                                      Contains("has no port of that name; the pass's ports: 'a', 'dst'"));
    }
    {
        RenderGraph g(gpu().device, {.label = "validate.misspelt"});
        g.setOutputSize({32, 32});
        const auto a = addFill(g, p, "a", 1);
        TextureHandle out;
        g.addPass("misspelt", [&](PassBuilder& builder) {
            builder.read("src", a);
            builder.read("source", a);   // no binding of copy.comp is called that
            out = builder.write("dst", builder.create("misspelt.out", {.format = kFormat}));
            const auto group = builder.bindGroup(p.copy);
            rhi::PushConstants params(p.copy);
            params.set("add", 0u);
            return [=, pipeline = p.copy](PassContext& ctx) { ctx.dispatch(pipeline, group, {32u, 32u}, params); };
        });
        g.markOutput(out);
        const auto error = test::errorFrom([&] { g.compile(); });
        REQUIRE(error);
        CHECK(error->kind() == ErrorKind::BindingMismatch);
        CHECK_THAT(error->what(), Contains("pass 'misspelt': port 'source' is bound to no binding of its shader"));
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("validate: a bind group whose storage format differs from the texture's", "[graph][validate][gpu]") {
    ValidationScope validation;
    const auto p = makePipelines();
    RenderGraph g(gpu().device, {.label = "validate.binding"});
    g.setOutputSize({32, 32});
    TextureHandle out;
    g.addPass("mismatch", [&](PassBuilder& b) {
        out = b.write("dst", b.create("wide", {.format = rhi::Format::RGBA16Float}));   // fill.comp wants r32ui
        const auto group = b.bindGroup(p.fill);
        rhi::PushConstants params(p.fill);
        params.set("seed", 0u);
        return [=, pipeline = p.fill](PassContext& ctx) { ctx.dispatch(pipeline, group, {32u, 32u}, params); };
    });
    g.markOutput(out);
    const auto error = test::errorFrom([&] { g.compile(); });
    REQUIRE(error);
    CHECK(error->kind() == ErrorKind::BindingMismatch);
    const std::string message = error->what();
    CHECK_THAT(message, StartsWith("pass 'mismatch': "));
    CHECK_THAT(message, Contains("'dst'"));
    CHECK_THAT(message, Contains("r32uint"));
    CHECK_THAT(message, Contains("rgba16float"));
    CHECK_THAT(message, Contains("formats differ"));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}
