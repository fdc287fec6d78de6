// Specialization constants (ComputePipelineDesc::constants): reflected by name, type,
// id and default; set by name when a pipeline is made; every mistake an error that
// names the pipeline and the constant.
#include <catch2/catch.hpp>

#include <bit>

#include <hush_test_shaders.hpp>

#include "support/gpu_context.hpp"

using namespace hush;
using namespace hush::rhi;
using namespace hush::test;

namespace {

ComputePipeline specialized(std::vector<ConstantEntry> constants) {
    return gpu().device.createComputePipeline(
        {.label = "specialized", .module = shaderModule("constants/specialized"), .constants = std::move(constants)});
}

// What the shader wrote: count, offset, scale's bits, and the sum 0 + 1 + ... + count-1.
std::vector<uint32_t> run(const ComputePipeline& pipeline) {
    auto& device = gpu().device;
    auto out = device.createBuffer({.label = "out", .size = 4 * 4, .usage = BufferUsage::Storage | BufferUsage::CopySrc});
    auto group = device.createBindGroup(
        {.label = "specialized", .layout = pipeline.getBindGroupLayout(0), .entries = {{.name = "result", .buffer = out}}});
    Readback back;
    submitAndWait([&](CommandEncoder& encoder) {
        encoder.barrier({}, {{out, ResourceState::Undefined, ResourceState::StorageWrite}});
        auto pass = encoder.beginComputePass({.label = "specialized"});
        pass.setPipeline(pipeline);
        pass.setBindGroup(0, group);
        pass.dispatchWorkgroups(1);
        pass.end();
        encoder.barrier({}, {{out, ResourceState::StorageWrite, ResourceState::CopySrc}});
        back = Readback::ofBuffer(encoder, out, 0, 4 * 4);
    });
    return back.values<uint32_t>();
}

std::string errorText(std::vector<ConstantEntry> constants) {
    const auto error = errorFrom([&] { specialized(std::move(constants)); });
    REQUIRE(error);
    CHECK(error->kind() == ErrorKind::InvalidArgument);
    return error->what();
}

} // namespace

TEST_CASE("specialization constants: reflected in id order with name, type and default", "[constants]") {
    const auto r = reflectComputeShader(hush::test_shaders::find("constants/specialized"), "specialized");
    REQUIRE(r.constants.size() == 3);
    CHECK(r.constants[0] == ShaderConstant{"offset", 1, ScalarType::Int32, -2.0});
    CHECK(r.constants[1] == ShaderConstant{"count", 3, ScalarType::Uint32, 4.0});
    CHECK(r.constants[2] == ShaderConstant{"scale", 7, ScalarType::Float32, 0.5});
}

TEST_CASE("specialization constants: the shader sees the defaults, or the values given by name", "[constants][gpu]") {
    ValidationScope validation;
    const auto defaults = run(specialized({}));
    CHECK(defaults == std::vector<uint32_t>{4u, std::bit_cast<uint32_t>(-2), std::bit_cast<uint32_t>(0.5f), 6u});
    const auto pipeline = specialized({{"scale", -1.25}, {"count", 10}});
    CHECK(pipeline.constants() == std::vector<ConstantEntry>{{"scale", -1.25}, {"count", 10}});
    const auto given = run(pipeline);
    CHECK(given == std::vector<uint32_t>{10u, std::bit_cast<uint32_t>(-2), std::bit_cast<uint32_t>(-1.25f), 45u});
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("specialization constants: an unknown or repeated name and an unrepresentable value are errors naming them",
          "[constants][gpu]") {
    ValidationScope validation;
    CHECK_THAT(errorText({{"cont", 1}}),
               Catch::Contains("pipeline 'specialized': constant 'cont': the shader has no such specialization "
                               "constant (it has 'offset', 'count', 'scale')"));
    CHECK_THAT(errorText({{"count", 1}, {"count", 2}}), Catch::Contains("constant 'count' is given twice"));
    CHECK_THAT(errorText({{"count", -1}}), Catch::Contains("constant 'count': -1.000000 is not a whole number in the uint range"));
    CHECK_THAT(errorText({{"count", 2.5}}), Catch::Contains("is not a whole number in the uint range"));
    CHECK_THAT(errorText({{"offset", 3e9}}), Catch::Contains("constant 'offset'"));
    CHECK_THAT(errorText({{"scale", 1e39}}), Catch::Contains("is not a finite float"));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}
