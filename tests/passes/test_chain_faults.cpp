// A chain runner under the driver's failures (injected: rhi/fault_injection.hpp) and
// under concurrency: out of device memory while the graph allocates, the device lost
// mid-sequence, and two runners on one device from two threads. Each failure is the
// hush::Error kind a caller can act on, destroying the broken runner is safe, and a
// runner built afterwards gives exactly the outputs of an undisturbed one.
#include <thread>

#include <catch2/catch.hpp>

#include <hush/passes/chain_file.hpp>
#include <hush/rhi/fault_injection.hpp>

#include "chain_test_util.hpp"
#include "support/gpu_context.hpp"

using namespace hush;
using namespace hush::passes_test;
using hush::test::errorFrom;

namespace {

constexpr size_t kFrames = 4;

std::vector<tracer::Frame> glossyFrames() {
    const auto& all = sceneSequence("glossy", 32);
    return {all.begin(), all.begin() + kFrames};
}

// Every frame's display output of `chain` on `device`.
std::vector<std::vector<float>> displays(const rhi::Device& device, const std::string& chain) {
    const auto input = glossyFrames();
    passes::ChainRunner runner(device, passes::makeChain(chain), {input[0].width, input[0].height});
    std::vector<std::vector<float>> out;
    for (const auto& frame : input) {
        uploadFrame(runner, frame);
        runner.run();
        out.push_back(runner.readDisplay());
    }
    return out;
}

struct DisarmAtExit {
    ~DisarmAtExit() { rhi::injectFault(rhi::InjectedFault::None); }
};

} // namespace

TEST_CASE("chain faults: out of device memory while the graph allocates, then a new runner is exact", "[faults][gpu]") {
    test::ValidationScope validation;
    DisarmAtExit disarm;
    const auto expected = displays(test::gpu().device, "svgf");
    for (uint32_t skip : {0u, 3u, 12u}) {   // the first, a middle and a late allocation
        INFO("the allocation that fails: " << skip + 1);
        rhi::injectFault(rhi::InjectedFault::OutOfDeviceMemory, skip);
        const auto error = errorFrom([] { displays(test::gpu().device, "svgf"); });
        REQUIRE(error);
        CHECK(error->kind() == ErrorKind::OutOfMemory);
        CHECK(displays(test::gpu().device, "svgf") == expected);
    }
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("chain faults: a device lost mid-sequence is DeviceLost, and a runner on a new device is exact", "[faults][gpu]") {
    test::ValidationScope validation;
    DisarmAtExit disarm;
    const auto expected = displays(test::gpu().device, "bmfr");
    const auto input = glossyFrames();
    {
        auto device = test::gpu().adapter.createDevice({.label = "to be lost"});
        passes::ChainRunner runner(device, passes::makeChain("bmfr"), {input[0].width, input[0].height});
        uploadFrame(runner, input[0]);
        runner.run();
        rhi::injectFault(rhi::InjectedFault::DeviceLost);
        const auto error = errorFrom([&] {
            uploadFrame(runner, input[1]);
            runner.run();
        });
        REQUIRE(error);
        CHECK(error->kind() == ErrorKind::DeviceLost);
        const auto later = errorFrom([&] { runner.run(); });   // still lost
        REQUIRE(later);
        CHECK(later->kind() == ErrorKind::DeviceLost);
    }   // the broken runner and its device are destroyed here without throwing
    auto fresh = test::gpu().adapter.createDevice({.label = "recreated"});
    CHECK(displays(fresh, "bmfr") == expected);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("chain faults: two runners on one device from two threads give the outputs each gives alone", "[faults][gpu]") {
    test::ValidationScope validation;
    const auto svgfAlone = displays(test::gpu().device, "svgf");
    const auto maraAlone = displays(test::gpu().device, "mara");
    std::vector<std::vector<float>> svgfThreaded, maraThreaded;
    std::exception_ptr failure[2];
    std::thread a([&] {
        try {
            svgfThreaded = displays(test::gpu().device, "svgf");
        } catch (...) {
            failure[0] = std::current_exception();
        }
    });
    std::thread b([&] {
        try {
            maraThreaded = displays(test::gpu().device, "mara");
        } catch (...) {
            failure[1] = std::current_exception();
        }
    });
    a.join();
    b.join();
    for (auto& f : failure)
        if (f) std::rethrow_exception(f);
    CHECK(svgfThreaded == svgfAlone);
    CHECK(maraThreaded == maraAlone);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}
