// layout: auto. Each binding kind, read back from pipeline.getBindGroupLayout(set)
// and from the module's reflection, compared field by field with what the shader
// source declares (tests/shaders/reflect/*.comp).
//
// Names: a block with an instance name reflects as that name (the shader's variable,
// as bind_group.hpp documents); an anonymous block has no variable name, so it
// reflects as its block name.
#include <catch2/catch.hpp>

#include "support/gpu_context.hpp"
#include <hush_test_shaders.hpp>

using namespace hush::rhi;
using namespace hush::test;

namespace {

BindGroupLayoutEntry entry(uint32_t binding, BindingKind kind, std::string name, Format format = Format::Undefined,
                           StorageAccess access = StorageAccess::ReadWrite) {
    return {.binding = binding, .kind = kind, .name = std::move(name), .storageFormat = format, .access = access};
}

const std::vector<BindGroupLayoutEntry>& allKindsSet0() {
    static const std::vector<BindGroupLayoutEntry> entries = {
        entry(0, BindingKind::UniformBuffer, "params"),
        entry(1, BindingKind::StorageBuffer, "RWBlock"),   // anonymous block
        entry(2, BindingKind::ReadOnlyStorageBuffer, "roData"),
        entry(3, BindingKind::SampledTexture, "sampledTex"),
        entry(4, BindingKind::Sampler, "plainSampler"),
        entry(5, BindingKind::CombinedTextureSampler, "combinedTex"),
        entry(6, BindingKind::StorageTexture, "imgRead", Format::RGBA16Float, StorageAccess::ReadOnly),
        entry(7, BindingKind::StorageTexture, "imgWrite", Format::R32Float, StorageAccess::WriteOnly),
        entry(8, BindingKind::StorageTexture, "imgReadWrite", Format::RGBA8Unorm, StorageAccess::ReadWrite),
        entry(9, BindingKind::StorageTexture, "counts", Format::R32Uint, StorageAccess::ReadWrite),
    };
    return entries;
}

const std::vector<BindGroupLayoutEntry>& allKindsSet1() {
    static const std::vector<BindGroupLayoutEntry> entries = {
        entry(0, BindingKind::StorageTexture, "maskOut", Format::R8Unorm, StorageAccess::WriteOnly),
        entry(2, BindingKind::StorageTexture, "motionIn", Format::RG16Float, StorageAccess::ReadOnly),
        entry(3, BindingKind::StorageTexture, "momentsOut", Format::RG32Float, StorageAccess::WriteOnly),
        entry(4, BindingKind::StorageTexture, "depthIn", Format::R16Float, StorageAccess::ReadOnly),
        entry(5, BindingKind::StorageBuffer, "histogram"),
    };
    return entries;
}

void checkEntries(const std::vector<BindGroupLayoutEntry>& got, const std::vector<BindGroupLayoutEntry>& want) {
    CHECK(got.size() == want.size());
    for (size_t i = 0; i < std::min(got.size(), want.size()); ++i) {
        INFO("entry " << i);
        CHECK(got[i] == want[i]);
    }
}

} // namespace

TEST_CASE("reflection: every binding kind reflects with its kind name format and access", "[reflection][gpu]") {
    ValidationScope validation;
    auto pipeline = computePipeline("reflect/all_kinds", "all kinds");
    REQUIRE(pipeline.bindGroupLayoutCount() == 2);
    SECTION("set 0: buffers, textures, samplers and storage images") {
        checkEntries(pipeline.getBindGroupLayout(0).entries(), allKindsSet0());
    }
    SECTION("set 1: extended storage formats, declared out of binding order") {
        checkEntries(pipeline.getBindGroupLayout(1).entries(), allKindsSet1());
    }
    SECTION("the module's reflection says the same") {
        const auto module = shaderModule("reflect/all_kinds");
        const auto& reflection = module.reflection();
        REQUIRE(reflection.sets.size() == 2);
        checkEntries(reflection.sets[0], allKindsSet0());
        checkEntries(reflection.sets[1], allKindsSet1());
        CHECK(reflection.entryPoint == "main");
        CHECK(reflection.workgroupSize == std::array<uint32_t, 3>{4, 2, 1});
        CHECK(reflection.pushConstantBytes == 20);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("reflection: push constant size and workgroup size", "[reflection][gpu]") {
    ValidationScope validation;
    auto allKinds = computePipeline("reflect/all_kinds", "all kinds");
    CHECK(allKinds.pushConstantBytes() == 20);   // std430 { vec4; uint; }
    CHECK(allKinds.workgroupSize() == std::array<uint32_t, 3>{4, 2, 1});
    auto sparse = computePipeline("reflect/sparse_sets", "sparse");
    CHECK(sparse.pushConstantBytes() == 0);
    CHECK(sparse.workgroupSize() == std::array<uint32_t, 3>{2, 3, 5});
    CHECK(sparse.label() == "sparse");
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("reflection: sets 0 and 2 with set 1 unused give an empty set 1", "[reflection][gpu]") {
    ValidationScope validation;
    auto pipeline = computePipeline("reflect/sparse_sets", "sparse");
    REQUIRE(pipeline.bindGroupLayoutCount() == 3);
    checkEntries(pipeline.getBindGroupLayout(0).entries(), {entry(0, BindingKind::StorageBuffer, "outData")});
    CHECK(pipeline.getBindGroupLayout(1).entries().empty());
    checkEntries(pipeline.getBindGroupLayout(2).entries(),
                 {entry(1, BindingKind::StorageTexture, "source", Format::RGBA32Float, StorageAccess::ReadOnly)});
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("reflection: reflectComputeShader needs no device", "[reflection]") {
    const auto reflection = reflectComputeShader(hush::test_shaders::find("reflect/sparse_sets"), "sparse (CPU)");
    CHECK(reflection.workgroupSize == std::array<uint32_t, 3>{2, 3, 5});
    CHECK(reflection.pushConstantBytes == 0);
    REQUIRE(reflection.sets.size() == 3);
    CHECK(reflection.sets[1].empty());
    checkEntries(reflection.sets[0], {entry(0, BindingKind::StorageBuffer, "outData")});
}

TEST_CASE("reflection: layouts look entries up by binding and by name", "[reflection][gpu]") {
    ValidationScope validation;
    auto layout = computePipeline("reflect/all_kinds", "all kinds").getBindGroupLayout(0);
    REQUIRE(layout.findBinding(7) != nullptr);
    CHECK(layout.findBinding(7)->name == "imgWrite");
    REQUIRE(layout.findName("counts") != nullptr);
    CHECK(layout.findName("counts")->binding == 9);
    CHECK(layout.findBinding(42) == nullptr);
    CHECK(layout.findName("noSuchName") == nullptr);
    // The spelling the header documents for messages.
    CHECK(describe(*layout.findBinding(6)) == "storage texture rgba16float (read-only)");
    CHECK(describe(entry(0, BindingKind::StorageTexture, "x", Format::RGBA16Float, StorageAccess::WriteOnly)) ==
          "storage texture rgba16float (write-only)");
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("reflection: bind groups for every kind are accepted by name", "[reflection][gpu]") {
    ValidationScope validation;
    auto& device = gpu().device;
    auto pipeline = computePipeline("reflect/all_kinds", "all kinds");
    auto storage = [&](Format f) {
        return device.createTexture({.label = std::string(toString(f)), .size = {8, 8}, .format = f,
                                     .usage = TextureUsage::StorageBinding});
    };
    auto sampled = device.createTexture(
        {.label = "sampled", .size = {8, 8}, .format = Format::RGBA16Float, .usage = TextureUsage::TextureBinding});
    auto sampler = device.createSampler();
    auto uniform = device.createBuffer({.label = "ubo", .size = 16, .usage = BufferUsage::Uniform});
    auto buffer = device.createBuffer({.label = "ssbo", .size = 256, .usage = BufferUsage::Storage});

    auto set0 = device.createBindGroup({.label = "all kinds 0",
                                        .layout = pipeline.getBindGroupLayout(0),
                                        .entries = {{.name = "params", .buffer = uniform},
                                                    {.name = "RWBlock", .buffer = buffer},
                                                    {.name = "roData", .buffer = buffer},
                                                    {.name = "sampledTex", .texture = sampled},
                                                    {.name = "plainSampler", .sampler = sampler},
                                                    {.name = "combinedTex", .texture = sampled, .sampler = sampler},
                                                    {.name = "imgRead", .texture = storage(Format::RGBA16Float)},
                                                    {.name = "imgWrite", .texture = storage(Format::R32Float)},
                                                    {.name = "imgReadWrite", .texture = storage(Format::RGBA8Unorm)},
                                                    {.name = "counts", .texture = storage(Format::R32Uint)}}});
    auto set1 = device.createBindGroup({.label = "all kinds 1",
                                        .layout = pipeline.getBindGroupLayout(1),
                                        .entries = {{.binding = 0, .texture = storage(Format::R8Unorm)},
                                                    {.binding = 2, .texture = storage(Format::RG16Float)},
                                                    {.binding = 3, .textureView = storage(Format::RG32Float).defaultView()},
                                                    {.binding = 4, .texture = storage(Format::R16Float)},
                                                    {.binding = 5, .buffer = buffer, .offset = 0, .size = 128}}});
    CHECK(set0.label() == "all kinds 0");
    CHECK(set0.layout() == pipeline.getBindGroupLayout(0));
    CHECK(set1.layout() == pipeline.getBindGroupLayout(1));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}
