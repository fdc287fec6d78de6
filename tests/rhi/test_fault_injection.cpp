// The driver failures no test machine produces on demand, injected (rhi/fault_injection.hpp):
// each becomes the hush::Error kind a caller can act on, a lost device stays lost, and
// the RHI's live-object counts return to where they were once the handles are gone.
#include <catch2/catch.hpp>

#include <hush/rhi/fault_injection.hpp>

#include "support/gpu_context.hpp"

using namespace hush::rhi;
using namespace hush::test;
using hush::ErrorKind;
using Catch::Matchers::Contains;

namespace {

Buffer smallBuffer(const Device& device, const char* label) {
    return device.createBuffer({.label = label, .size = 256, .usage = BufferUsage::Storage | BufferUsage::CopyDst | BufferUsage::CopySrc});
}

// Disarms whatever a failed check left armed, so one test cannot break the next.
struct DisarmAtExit {
    ~DisarmAtExit() { injectFault(InjectedFault::None); }
};

} // namespace

TEST_CASE("faults: an injected out-of-device-memory is OutOfMemory once, then allocation works", "[faults][gpu]") {
    ValidationScope validation;
    DisarmAtExit disarm;
    const Device& device = gpu().device;
    const uint64_t before = device.allocatedBytes();
    {
        injectFault(InjectedFault::OutOfDeviceMemory, 1);   // the second allocation from now
        auto first = smallBuffer(device, "first");
        const auto error = errorFrom([&] { smallBuffer(device, "second"); });
        REQUIRE(error);
        CHECK(error->kind() == ErrorKind::OutOfMemory);
        CHECK_THAT(error->what(), Contains("second") && Contains("out of device memory"));
        auto third = smallBuffer(device, "third");   // disarmed after one failure
    }
    CHECK(device.allocatedBytes() == before);   // the failed allocation left nothing behind
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("faults: an injected device loss fails every later submission and wait on that device only", "[faults][gpu]") {
    ValidationScope validation;
    DisarmAtExit disarm;
    auto lostDevice = gpu().adapter.createDevice({.label = "to be lost"});
    auto queue = lostDevice.queue();
    auto buffer = smallBuffer(lostDevice, "data");
    const std::vector<std::byte> bytes(256, std::byte{7});
    queue.writeBuffer(buffer, 0, bytes);   // works before the loss
    injectFault(InjectedFault::DeviceLost);
    auto encoder = lostDevice.createCommandEncoder({.label = "after loss"});
    const auto error = errorFrom([&] { queue.submit(encoder.finish()); });
    REQUIRE(error);
    CHECK(error->kind() == ErrorKind::DeviceLost);
    CHECK_THAT(error->what(), Contains("recreate the Device"));
    const auto again = errorFrom([&] { queue.readBuffer(buffer); });
    REQUIRE(again);
    CHECK(again->kind() == ErrorKind::DeviceLost);

    // Another device (the shared one) is untouched, and a new device works.
    auto other = smallBuffer(gpu().device, "other");
    gpu().queue().writeBuffer(other, 0, bytes);
    CHECK(gpu().queue().readBuffer(other) == bytes);
    auto fresh = gpu().adapter.createDevice({.label = "recreated"});
    auto freshBuffer = smallBuffer(fresh, "data");
    fresh.queue().writeBuffer(freshBuffer, 0, bytes);
    CHECK(fresh.queue().readBuffer(freshBuffer) == bytes);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("faults: fault names parse, and anything else names the choices", "[faults]") {
    CHECK(parseInjectedFault("device-lost") == InjectedFault::DeviceLost);
    CHECK(parseInjectedFault("out-of-device-memory") == InjectedFault::OutOfDeviceMemory);
    CHECK(parseInjectedFault("none") == InjectedFault::None);
    const auto error = errorFrom([] { parseInjectedFault("oom"); });
    REQUIRE(error);
    CHECK_THAT(error->what(), Contains("'oom'") && Contains("device-lost"));
}

TEST_CASE("live objects: each kind counts up on creation and back down on release", "[faults][gpu]") {
    ValidationScope validation;
    gpu();   // the shared instance and device exist before the count starts
    const LiveObjects before = liveObjects();
    {
        auto buffer = smallBuffer(gpu().device, "counted");
        auto texture = gpu().device.createTexture({.label = "counted", .size = {4, 4}, .format = Format::RGBA32Float,
                                                   .usage = TextureUsage::StorageBinding});
        const LiveObjects during = liveObjects();
        CHECK(during[ObjectKind::Buffer] == before[ObjectKind::Buffer] + 1);
        CHECK(during[ObjectKind::Texture] == before[ObjectKind::Texture] + 1);
        CHECK(during.total() >= before.total() + 2);
    }
    gpu().queue().waitIdle();   // retires what the submissions kept alive
    const LiveObjects after = liveObjects();
    for (std::size_t k = 0; k < kObjectKindCount; ++k) {
        INFO(toString(ObjectKind(k)));
        CHECK(after.count[k] == before.count[k]);
    }
    CHECK(std::string(toString(ObjectKind::BindGroupLayout)) == "bind group layout");
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}
