#pragma once
// The declared graph as plain data. RenderGraph's builder fills it; each compile
// step (compile_steps.hpp) reads it, so every step can be tested on a model built
// by hand, including models the builder could never produce (cycles, two writers).
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <hush/graph/handles.hpp>
#include <hush/rhi/format.hpp>
#include <hush/rhi/resource_state.hpp>

namespace hush::graph {

// A texture's extent: fixed, or a fraction of the graph's output size (so a chain
// follows the window / frame size without being declared again).
struct SizeSpec {
    enum class Mode : uint8_t { Absolute, RelativeToOutput };
    Mode mode = Mode::RelativeToOutput;
    rhi::Extent2D extent;   // Absolute
    float scale = 1.0f;     // RelativeToOutput: round(output * scale), at least 1
    // RelativeToOutput: the output is first rounded up to a multiple of `padTo` (a
    // network that pools k times runs on a multiple of 2^k), and the scaled extent
    // is repeated in a grid of tiles (a tensor's channel blocks side by side,
    // passes/rdae/tensor.hpp).
    uint32_t padTo = 1;
    uint32_t tilesX = 1;
    uint32_t tilesY = 1;

    static SizeSpec absolute(uint32_t width, uint32_t height) { return {Mode::Absolute, {width, height}, 1.0f}; }
    static SizeSpec relative(float s = 1.0f) { return {Mode::RelativeToOutput, {}, s}; }
    static SizeSpec tiled(float s, uint32_t padTo, uint32_t tilesX, uint32_t tilesY) {
        return {Mode::RelativeToOutput, {}, s, padTo, tilesX, tilesY};
    }
    rhi::Extent2D resolve(rhi::Extent2D output) const;
    friend bool operator==(const SizeSpec&, const SizeSpec&) = default;
};

struct TextureInfo {
    rhi::Format format = rhi::Format::RGBA16Float;
    SizeSpec size;
    friend bool operator==(const TextureInfo&, const TextureInfo&) = default;
};

struct BufferInfo {
    uint64_t size = 0;
    // When set, the size follows the graph's output size: compile calls it with the
    // output extent (a per-block matrix of BMFR's fit grows with the image), and a
    // size change recompiles. `size` is then unused.
    std::function<uint64_t(rhi::Extent2D output)> sizeFromOutput;

    uint64_t resolve(rhi::Extent2D output) const { return sizeFromOutput ? sizeFromOutput(output) : size; }
    // Two infos with size functions compare equal (functions cannot be compared).
    friend bool operator==(const BufferInfo& a, const BufferInfo& b) {
        return a.size == b.size && bool(a.sizeFromOutput) == bool(b.sizeFromOutput);
    }
};

enum class ResourceKind : uint8_t { Texture, Buffer };
enum class ResourceOrigin : uint8_t {
    Transient,   // created by a pass; lives within a frame; may share memory
    Imported,    // the application's (inputs, output image)
    History,     // last frame's final value of the transient it is bound to (historySource)
};

// How a pass uses a resource. Writes produce the next version.
// IndirectRead: a buffer that holds a dispatch's workgroup counts and is read by its
// shader too (PassBuilder::readIndirect).
enum class Access : uint8_t {
    SampledRead, StorageRead, StorageWrite, StorageReadWrite, UniformRead, IndirectRead, CopySrc, CopyDst
};
bool isWrite(Access access);
bool isRead(Access access);
rhi::ResourceState toState(Access access);
const char* toString(Access access);

struct ResourceDecl {
    std::string name;
    ResourceKind kind = ResourceKind::Texture;
    ResourceOrigin origin = ResourceOrigin::Transient;
    TextureInfo texture;
    BufferInfo buffer;
    uint32_t versionCount = 1;   // versions 0 .. versionCount-1 were handed out
    // Imported: the state the application leaves it in before the frame and wants after.
    rhi::ResourceState initialState = rhi::ResourceState::Undefined;
    rhi::ResourceState finalState = rhi::ResourceState::General;
    bool output = false;         // markOutput: its last version must be computed
    // History: the transient texture whose end-of-frame value this holds (kNone: not
    // bound yet; RenderGraph::bindHistory).
    uint32_t historySource = kNone;
};

struct AccessDecl {
    std::string port;              // the pass's name for this input/output ("motion")
    uint32_t resource = kNone;     // kNone: the port was left unconnected
    uint32_t version = 0;          // the version read, or written over (producing version + 1)
    Access access = Access::StorageRead;
    bool optional = false;         // an optional input may stay unconnected
    uint32_t latestAtDeclaration = 0;   // the resource's newest version when declared
    std::optional<rhi::Format> expectFormat;   // what the pass requires of the input
    std::optional<SizeSpec> expectSize;
};

struct PassDecl {
    std::string name;
    std::vector<AccessDecl> accesses;
    bool sideEffect = false;   // kept even if nothing reads what it writes
};

struct GraphModel {
    std::vector<ResourceDecl> resources;
    std::vector<PassDecl> passes;
    rhi::Extent2D outputSize{1, 1};

    // The transient whose end-of-frame value a History resource holds (kNone when
    // unbound, or when the resource is not a history).
    uint32_t historySource(uint32_t historyResource) const;
};

} // namespace hush::graph
