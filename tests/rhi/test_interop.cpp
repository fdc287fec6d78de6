// Interop: the test plays an engine. It makes its own VkInstance (with the validation
// layer and synchronization validation, reporting into the tests' log), VkDevice
// (Vulkan 1.3, timelineSemaphore + synchronization2), VkQueue, VkBuffer + memory and
// VkImage, hands them to hush, runs hush compute work on them, and reads the results
// back through its own mapping. Then it records hush commands into its own command
// buffer and submits that itself. Raw objects are destroyed after hush's handles.
// The engine side lives in support/raw_vulkan.{hpp,cpp}.
#include <volk.h>

#include <catch2/catch.hpp>

#include <memory>
#include <vector>

#include <hush/rhi/vulkan_interop.hpp>

#include "support/gpu_context.hpp"
#include "support/raw_vulkan.hpp"
#include <hush_test_shaders.hpp>

using namespace hush::rhi;
using namespace hush::test;

namespace {

constexpr uint32_t kW = 32, kH = 24;

// The engine's objects, a hush Device imported over them, hush handles wrapping its
// image and buffer, and the two pipelines. Members are destroyed in reverse order:
// hush's handles first, then (with `raw`) the engine's objects.
struct Engine {
    std::unique_ptr<RawVulkan> raw = std::make_unique<RawVulkan>();
    Device device;
    Texture texture;
    Buffer buffer;
    ComputePipeline write, accumulate;
    BindGroup writeGroup, accumulateGroup;

    Engine() {
        raw->createInstance();
        raw->pickPhysicalDevice();
        raw->createDevice();
        raw->createBuffer(kW * kH * 4);
        raw->createImage(kW, kH);
        device = importVulkanDevice({.instance = raw->instance,
                                     .physicalDevice = raw->physical,
                                     .device = raw->device,
                                     .queue = raw->queue,
                                     .queueFamilyIndex = raw->family,
                                     .getInstanceProcAddr = vkGetInstanceProcAddr,
                                     .label = "engine"});
        texture = wrapVulkanImage(device, raw->image,
                                  {.label = "engine image", .size = {kW, kH}, .format = Format::RGBA32Float,
                                   .usage = TextureUsage::StorageBinding | TextureUsage::CopySrc | TextureUsage::CopyDst});
        buffer = wrapVulkanBuffer(device, raw->buffer,
                                  {.label = "engine buffer", .size = kW * kH * 4,
                                   .usage = BufferUsage::Storage | BufferUsage::CopySrc | BufferUsage::CopyDst});
        write = pipeline("interop/write");
        accumulate = pipeline("interop/accumulate");
        writeGroup = device.createBindGroup({.label = "write",
                                             .layout = write.getBindGroupLayout(0),
                                             .entries = {{.binding = 0, .texture = texture}, {.binding = 1, .buffer = buffer}}});
        accumulateGroup = device.createBindGroup({.label = "accumulate",
                                                  .layout = accumulate.getBindGroupLayout(0),
                                                  .entries = {{.binding = 0, .texture = texture}, {.binding = 1, .buffer = buffer}}});
    }

    ComputePipeline pipeline(const char* name) const {
        auto module = device.createShaderModule({.label = name, .code = hush::test_shaders::find(name)});
        return device.createComputePipeline({.label = name, .module = module});
    }

    // interop/write.comp through hush's own command buffer on the engine's queue. Leaves
    // the image in StorageRead and the buffer in HostRead.
    void runWrite() {
        auto encoder = device.createCommandEncoder({.label = "hush on engine device"});
        encoder.barrier({{texture, ResourceState::Undefined, ResourceState::StorageWrite}},
                        {{buffer, ResourceState::Undefined, ResourceState::StorageWrite}});
        dispatch(encoder, write, writeGroup);
        encoder.barrier({{texture, ResourceState::StorageWrite, ResourceState::StorageRead}},
                        {{buffer, ResourceState::StorageWrite, ResourceState::HostRead}});
        auto queue = device.queue();
        queue.wait(queue.submit(encoder.finish()));
    }

    static void dispatch(CommandEncoder& encoder, const ComputePipeline& pipeline, const BindGroup& group) {
        auto pass = encoder.beginComputePass({.label = pipeline.label()});
        pass.setPipeline(pipeline);
        pass.setBindGroup(0, group);
        pass.dispatchThreads(kW, kH);
        pass.end();
    }

    // Destroys everything now (hush's handles, then the engine's objects), so that a
    // check after this sees the messages from teardown too.
    void release() {
        if (device) device.waitIdle();
        accumulateGroup = {};
        writeGroup = {};
        accumulate = {};
        write = {};
        buffer = {};
        texture = {};
        device = {};
        raw.reset();
    }
};

// interop/write.comp:      image = (x, y, x*y, 1), values[i] = x + 1000 y
// interop/accumulate.comp: values[i] = values[i] * 2 + uint(image.z)
// Exact: small integers in fp32 and uint32.
std::vector<uint32_t> expectedFirst() {
    std::vector<uint32_t> out(kW * kH);
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x) out[y * kW + x] = x + 1000 * y;
    return out;
}
std::vector<uint32_t> expectedSecond() {
    auto out = expectedFirst();
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x) out[y * kW + x] = out[y * kW + x] * 2 + x * y;
    return out;
}
std::vector<float> expectedImage() {
    std::vector<float> out;
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x)
            for (float v : {float(x), float(y), float(x * y), 1.0f}) out.push_back(v);
    return out;
}

} // namespace

TEST_CASE("interop: hush runs on an application's VkDevice and writes its VkImage and VkBuffer", "[interop][gpu]") {
    ValidationScope validation;
    {
        Engine engine;
        CHECK(vulkanDevice(engine.device) == engine.raw->device);
        CHECK(engine.device.adapterInfo().name == engine.raw->name);
        CHECK(vulkanImage(engine.texture) == engine.raw->image);
        CHECK(vulkanBuffer(engine.buffer) == engine.raw->buffer);
        CHECK(vulkanFormat(Format::RGBA32Float) == VK_FORMAT_R32G32B32A32_SFLOAT);
        CHECK(engine.texture.size() == Extent2D{kW, kH});
        CHECK(engine.buffer.size() == kW * kH * 4);

        engine.runWrite();
        CHECK(engine.raw->mappedValues(kW * kH) == expectedFirst());   // through the engine's own mapping
        CHECK(valuesOf<float>(engine.device.queue().readTexture({.texture = engine.texture, .state = ResourceState::StorageRead})) ==
              expectedImage());
        engine.release();
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("interop: hush records into an application's command buffer that it submits", "[interop][gpu]") {
    ValidationScope validation;
    {
        Engine engine;
        engine.runWrite();
        VkCommandBuffer cmd = engine.raw->beginCommands();
        {   // hush handles (the encoder holds the device) go before engine.release()
            auto encoder = encodeIntoVulkanCommandBuffer(engine.device, cmd);
            encoder.bufferBarrier({{engine.buffer, ResourceState::HostRead, ResourceState::StorageReadWrite}});
            Engine::dispatch(encoder, engine.accumulate, engine.accumulateGroup);   // the image stays in StorageRead
            encoder.bufferBarrier({{engine.buffer, ResourceState::StorageReadWrite, ResourceState::HostRead}});
            auto finished = encoder.finish();
            CHECK_FALSE(finished);   // vulkan_interop.hpp: "finish() returns an empty CommandBuffer"
            CHECK_THROWS_AS(engine.device.queue().submit(finished), hush::Error);   // never submitted through hush
        }
        engine.raw->submitAndWait(cmd);
        CHECK(engine.raw->mappedValues(kW * kH) == expectedSecond());
        engine.release();
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}
