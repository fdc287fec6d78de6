// Push constants written by name (rhi/push_constants.hpp): the shader's block is
// reflected member by member, every write is checked against it, and what reaches the
// shader is exactly what was written.
#include <catch2/catch.hpp>

#include <array>
#include <cstring>

#include <hush/rhi/push_constants.hpp>

#include <hush_test_shaders.hpp>

#include "support/gpu_context.hpp"

using namespace hush;
using namespace hush::rhi;
using namespace hush::test;

TEST_CASE("push constants: members reflect with name, offset, type and size", "[push-constants]") {
    const auto r = reflectComputeShader(hush::test_shaders::find("push/members"), "members");
    REQUIRE(r.pushConstants.size() == 5);
    CHECK(r.pushConstants[0] == PushConstantMember{"scale", 0, ScalarType::Float32, 1, 1});
    CHECK(r.pushConstants[1] == PushConstantMember{"offset", 4, ScalarType::Int32, 1, 1});
    CHECK(r.pushConstants[2] == PushConstantMember{"flags", 8, ScalarType::Uint32, 1, 1});
    CHECK(r.pushConstants[3] == PushConstantMember{"uv", 16, ScalarType::Float32, 2, 1});
    CHECK(r.pushConstants[4] == PushConstantMember{"codes", 32, ScalarType::Uint32, 4, 2});
    CHECK(r.pushConstantBytes == 64);
}

TEST_CASE("push constants: a wrong name, type or size and a member never written are errors naming it",
          "[push-constants][gpu]") {
    ValidationScope validation;
    const auto pipeline = computePipeline("push/members", "members");
    PushConstants p(pipeline);
    auto error = errorFrom([&] { p.set("scal", 1.0f); });
    REQUIRE(error);
    CHECK(error->kind() == ErrorKind::BindingMismatch);
    CHECK_THAT(error->what(), Catch::Contains("pipeline 'members' has no push constant 'scal'; its push constants: "
                                              "scale, offset, flags, uv, codes"));
    error = errorFrom([&] { p.set("flags", 1.0f); });
    REQUIRE(error);
    CHECK_THAT(error->what(), Catch::Contains("push constant 'flags' is uint in the shader, written as float"));
    error = errorFrom([&] { p.set("uv", {1.0f, 2.0f, 3.0f}); });
    REQUIRE(error);
    CHECK_THAT(error->what(), Catch::Contains("push constant 'uv' is 2 x float in the shader, written as 3 x float"));
    p.set("scale", 2.0f).set("offset", int32_t(-3)).set("uv", {0.25f, 0.5f});
    CHECK_FALSE(p.complete());
    error = errorFrom([&] { p.requireComplete(); });
    REQUIRE(error);
    CHECK_THAT(error->what(), Catch::Contains("pipeline 'members': push constant 'flags' is never written"));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("push constants: the shader reads exactly the values written by name", "[push-constants][gpu]") {
    ValidationScope validation;
    auto& device = gpu().device;
    const auto pipeline = computePipeline("push/members", "members");
    PushConstants p(pipeline);
    const std::array<uint32_t, 8> codes{1, 2, 3, 4, 5, 6, 7, 0xFFFFFFFFu};
    p.set("scale", 1.5f).set("offset", int32_t(-7)).set("uv", {0.25f, -4.0f}).set("codes", codes);
    const auto flags = p.slot("flags", ScalarType::Uint32);
    p.set(flags, 42u);
    REQUIRE(p.complete());
    auto out = device.createBuffer({.label = "out", .size = 13 * 4, .usage = BufferUsage::Storage | BufferUsage::CopySrc});
    auto group = device.createBindGroup(
        {.label = "members", .layout = pipeline.getBindGroupLayout(0), .entries = {{.name = "result", .buffer = out}}});
    Readback back;
    submitAndWait([&](CommandEncoder& encoder) {
        encoder.barrier({}, {{out, ResourceState::Undefined, ResourceState::StorageWrite}});
        auto pass = encoder.beginComputePass({.label = "members"});
        pass.setPipeline(pipeline);
        pass.setBindGroup(0, group);
        pass.setPushConstants(p);
        pass.dispatchWorkgroups(1);
        pass.end();
        encoder.barrier({}, {{out, ResourceState::StorageWrite, ResourceState::CopySrc}});
        back = Readback::ofBuffer(encoder, out, 0, 13 * 4);
    });
    const auto v = back.values<uint32_t>();
    auto bits = [](float f) {
        uint32_t u;
        std::memcpy(&u, &f, 4);
        return u;
    };
    CHECK(v[0] == bits(1.5f));
    CHECK(int32_t(v[1]) == -7);
    CHECK(v[2] == 42u);
    CHECK(v[3] == bits(0.25f));
    CHECK(v[4] == bits(-4.0f));
    for (size_t i = 0; i < 8; ++i) CHECK(v[5 + i] == codes[i]);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}
