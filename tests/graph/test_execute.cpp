// Executing a compiled graph: it recompiles only when its structure or sizes change,
// and running it frame after frame allocates nothing.
//
// This translation unit replaces the global operator new (and delete) with versions
// that forward to malloc / free and count calls made on a thread while counting is
// switched on for it. Only the allocation test switches it on.
//
// The tests run with the Vulkan validation layer, which allocates inside nearly every
// vkCmd* call. Those allocations are the layer's, not hush's: an allocation whose call
// stack passes through the layer's code is counted apart.
#include <catch2/catch.hpp>

#include <array>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>
#include <sstream>

#include <execinfo.h>
#include <link.h>

#include "graph/graph_test_util.hpp"

namespace {

thread_local bool tCounting = false;
std::atomic<size_t> gAllocations{0};        // hush's (and anything else not the layer's)
std::atomic<size_t> gLayerAllocations{0};   // the validation layer's

// Where the validation layer's code is mapped.
struct AddressRange {
    uintptr_t begin = 0, end = 0;
};
std::array<AddressRange, 16> gLayerCode{};
size_t gLayerCodeCount = 0;

int findLayerCode(dl_phdr_info* info, size_t, void*) {
    if (!info->dlpi_name || !std::strstr(info->dlpi_name, "VkLayer_khronos_validation")) return 0;
    for (int i = 0; i < info->dlpi_phnum; ++i) {
        const auto& segment = info->dlpi_phdr[i];
        if (segment.p_type != PT_LOAD || !(segment.p_flags & PF_X) || gLayerCodeCount == gLayerCode.size()) continue;
        const uintptr_t begin = info->dlpi_addr + segment.p_vaddr;
        gLayerCode[gLayerCodeCount++] = {begin, begin + segment.p_memsz};
    }
    return 0;
}

bool inLayer(const void* address) {
    const auto a = reinterpret_cast<uintptr_t>(address);
    for (size_t i = 0; i < gLayerCodeCount; ++i)
        if (a >= gLayerCode[i].begin && a < gLayerCode[i].end) return true;
    return false;
}

// The call stacks of the first few counted allocations, to say where they came from.
constexpr int kStacks = 4, kDepth = 48;
std::array<std::array<void*, kDepth>, kStacks> gStacks{};
std::array<int, kStacks> gStackDepth{};

void count() {
    tCounting = false;   // backtrace() must not count (it allocates nothing once warm)
    std::array<void*, kDepth> stack;
    const int depth = backtrace(stack.data(), kDepth);
    bool layer = false;
    for (int i = 0; i < depth && !layer; ++i) layer = inLayer(stack[size_t(i)]);
    if (layer) {
        gLayerAllocations.fetch_add(1, std::memory_order_relaxed);
    } else {
        const size_t n = gAllocations.fetch_add(1, std::memory_order_relaxed);
        if (n < size_t(kStacks)) {
            gStacks[n] = stack;
            gStackDepth[n] = depth;
        }
    }
    tCounting = true;
}

void* allocate(std::size_t bytes, std::size_t alignment) {
    if (tCounting) count();
    if (bytes == 0) bytes = 1;
    void* p = alignment <= alignof(std::max_align_t)
                  ? std::malloc(bytes)
                  : std::aligned_alloc(alignment, (bytes + alignment - 1) / alignment * alignment);
    if (!p) throw std::bad_alloc();
    return p;
}

void* allocateNoThrow(std::size_t bytes, std::size_t alignment) noexcept {
    try {
        return allocate(bytes, alignment);
    } catch (...) {
        return nullptr;
    }
}

// Counts operator new calls on this thread while alive.
class CountAllocations {
public:
    CountAllocations() {
        gLayerCodeCount = 0;
        dl_iterate_phdr(findLayerCode, nullptr);
        void* warm[2];
        backtrace(warm, 2);   // the first call loads the unwinder, which allocates
        gAllocations = 0;
        gLayerAllocations = 0;
        tCounting = true;
    }
    ~CountAllocations() { tCounting = false; }
    CountAllocations(const CountAllocations&) = delete;
    CountAllocations& operator=(const CountAllocations&) = delete;

    size_t count() const { return gAllocations.load(); }
    size_t layerCount() const { return gLayerAllocations.load(); }

    // Where the first allocations came from (addresses: resolve with addr2line -i -f -C -e).
    static std::string stacks() {
        std::ostringstream out;
        const size_t n = std::min<size_t>(gAllocations.load(), kStacks);
        for (size_t i = 0; i < n; ++i) {
            out << "allocation " << i << ":\n";
            char** symbols = backtrace_symbols(gStacks[i].data(), gStackDepth[i]);
            for (int k = 0; k < gStackDepth[i] && symbols; ++k) out << "  " << symbols[k] << "\n";
            std::free(symbols);
        }
        return out.str();
    }
};

} // namespace

void* operator new(std::size_t n) { return allocate(n, 0); }
void* operator new[](std::size_t n) { return allocate(n, 0); }
void* operator new(std::size_t n, std::align_val_t a) { return allocate(n, std::size_t(a)); }
void* operator new[](std::size_t n, std::align_val_t a) { return allocate(n, std::size_t(a)); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return allocateNoThrow(n, 0); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return allocateNoThrow(n, 0); }
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
    return allocateNoThrow(n, std::size_t(a));
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
    return allocateNoThrow(n, std::size_t(a));
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }

using namespace hush;
using namespace hush::graph;
using namespace hush::graph_test;
using hush::test::gpu;
using hush::test::ValidationScope;

namespace {

// fill, fill -> combine -> copy -> output, all sizes relative to the output size.
struct SmallGraph {
    Pipelines p;
    RenderGraph g;
    TextureHandle out;

    explicit SmallGraph(rhi::Extent2D size, const rhi::Device& device = gpu().device)
        : p(makePipelines(device)), g(device, {.label = "execute"}) {
        g.setOutputSize(size);
        const auto a = addFill(g, p, "a", 10);
        const auto b = addFill(g, p, "b", 20, SizeSpec::relative(1.0f));
        const auto c = addCombine(g, p, "c", a, b, {3, 5, 7, 3});
        out = addCopy(g, p, "d", c, 9);
        g.markOutput(out);
    }

    std::vector<uint32_t> expected(rhi::Extent2D size) const {
        const auto a = fillImage(10, size.width, size.height), b = fillImage(20, size.width, size.height);
        std::vector<uint32_t> r(a.size());
        for (uint32_t y = 0; y < size.height; ++y)
            for (uint32_t x = 0; x < size.width; ++x) {
                const size_t i = size_t(y) * size.width + x;
                r[i] = combineReference(a[i], b[i], {3, 5, 7, 3}, x, y) + 9;
            }
        return r;
    }
};

} // namespace

TEST_CASE("execute: no recompilation while nothing changes", "[graph][execute][gpu]") {
    ValidationScope validation;
    SmallGraph s({64, 48});
    CHECK(s.g.needsCompile());
    CHECK(s.g.compileCount() == 0);
    for (int frame = 0; frame < 40; ++frame) s.g.execute();
    s.g.waitIdle();
    CHECK(s.g.compileCount() == 1);
    CHECK_FALSE(s.g.needsCompile());
    CHECK(s.g.frameCount() == 40);
    CHECK(readOutput(s.g, s.out) == s.expected({64, 48}));

    s.g.setOutputSize({64, 48});   // the same size: nothing to do
    CHECK_FALSE(s.g.needsCompile());
    s.g.execute();
    CHECK(s.g.compileCount() == 1);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("execute: a new output size recompiles once, with textures of the new size", "[graph][execute][gpu]") {
    ValidationScope validation;
    SmallGraph s({64, 48});
    s.g.execute();
    s.g.setOutputSize({37, 29});   // odd sizes: partial workgroups
    CHECK(s.g.needsCompile());
    for (int frame = 0; frame < 5; ++frame) s.g.execute();
    s.g.waitIdle();
    CHECK(s.g.compileCount() == 2);
    CHECK(s.g.outputSize() == rhi::Extent2D{37, 29});
    CHECK(s.g.outputTexture(s.out).size() == rhi::Extent2D{37, 29});
    CHECK(readOutput(s.g, s.out) == s.expected({37, 29}));

    s.g.setOutputSize({37, 29});
    s.g.execute();
    CHECK(s.g.compileCount() == 2);
    s.g.setOutputSize({64, 48});
    s.g.execute();
    s.g.waitIdle();
    CHECK(s.g.compileCount() == 3);
    CHECK(readOutput(s.g, s.out) == s.expected({64, 48}));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("execute: a structural change recompiles", "[graph][execute][gpu]") {
    ValidationScope validation;
    SmallGraph s({32, 32});
    s.g.execute();
    CHECK(s.g.compileCount() == 1);
    const auto extra = addCopy(s.g, s.p, "e", s.out, 1);   // a new pass
    s.g.markOutput(extra);
    CHECK(s.g.needsCompile());
    s.g.execute();
    s.g.waitIdle();
    CHECK(s.g.compileCount() == 2);
    auto expected = s.expected({32, 32});
    for (auto& v : expected) ++v;
    CHECK(readOutput(s.g, extra) == expected);
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("execute: running a compiled graph frame after frame allocates nothing", "[graph][execute][gpu]") {
    ValidationScope validation;
    SmallGraph s({64, 48});
    auto input = makeTexture("input", 64, 48);
    upload(input, fillImage(5, 64, 48), ResourceState::Undefined, ResourceState::StorageRead);
    // A history and an imported texture too, so that every kind of resource is in play.
    const auto in = s.g.importTexture(
        "input", input, {.initialState = ResourceState::StorageRead, .finalState = ResourceState::StorageRead});
    TextureHandle acc;
    s.g.addPass("accumulate", [&](PassBuilder& b) {
        const auto sum = b.create("acc", {.format = kFormat});
        b.read("history", s.g.history(sum));
        b.read("current", in);
        acc = b.write("acc", sum);
        b.write("seen", b.create("seen", {.format = kFormat}));
        const auto group = b.bindGroup(s.p.accumulate);
        rhi::PushConstants params(s.p.accumulate);
        params.set("add", 1u);
        const auto historyValid = params.slot("historyValid", rhi::ScalarType::Uint32);
        return [group, pipeline = s.p.accumulate, params, historyValid](PassContext& ctx) mutable {
            params.set(historyValid, ctx.historyValid() ? 1u : 0u);
            ctx.dispatch(pipeline, group, {64u, 48u}, params);
        };
    });
    s.g.markOutput(acc);

    for (int frame = 0; frame < 3; ++frame) s.g.execute();   // warm-up: compile, fill the frames in flight
    s.g.waitIdle();

    constexpr int kFrames = 20;
    size_t allocations = 0, layerAllocations = 0;
    std::string stacks;
    {
        CountAllocations counter;
        for (int frame = 0; frame < kFrames; ++frame) s.g.execute();
        s.g.waitIdle();
        allocations = counter.count();
        layerAllocations = counter.layerCount();
        stacks = CountAllocations::stacks();
    }
    INFO(allocations << " operator new call(s) in " << kFrames << " frames (and " << layerAllocations
                     << " by the validation layer, not counted)\n"
                     << stacks);
    CHECK(allocations == 0);
    CHECK(s.g.compileCount() == 1);
    CHECK(s.g.frameCount() == 3 + kFrames);
    CHECK(s.g.timings().valid);
    CHECK(readOutput(s.g, s.out) == s.expected({64, 48}));
    HUSH_REQUIRE_NO_VALIDATION_MESSAGES(validation);
}

TEST_CASE("execute: the counting operator new sees allocations", "[graph][execute]") {
    // The allocation test's zero means something only if the counter works.
    size_t counted = 0, layer = 0;
    {
        CountAllocations counter;
        auto* volatile p = new int(7);
        delete p;
        std::vector<int> v(100);
        counted = counter.count();
        layer = counter.layerCount();
    }
    CHECK(counted == 2);
    CHECK(layer == 0);
}
