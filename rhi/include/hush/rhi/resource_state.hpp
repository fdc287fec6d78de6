#pragma once
// How a resource is used at a point in a command stream. The RHI tracks no state:
// whoever records (the render graph, or a hand-written test) states the before and
// after of every transition, and the RHI turns that into one Vulkan barrier.
#include <cstdint>
#include <string_view>

namespace hush::rhi {

enum class ResourceState : uint8_t {
    Undefined,         // contents may be discarded (first use, or aliased memory)
    CopySrc,
    CopyDst,
    SampledRead,       // texture sampled by a compute shader (read-only layout)
    StorageRead,       // imageLoad / readonly buffer in a compute shader
    StorageWrite,      // imageStore / buffer write in a compute shader
    StorageReadWrite,  // both in one dispatch
    UniformRead,       // uniform buffer
    IndirectRead,      // a dispatch's workgroup counts, and read by that dispatch's shader
    HostRead,          // mapped and read by the CPU after the GPU wrote it
    HostWrite,         // written by the CPU before the GPU reads it
    General,           // anything, any stage: for interop hand-offs to an engine
};

std::string_view toString(ResourceState state);

// True when moving between the two states needs no barrier: both only read and,
// for textures, share one image layout.
bool isReadOnly(ResourceState state);

} // namespace hush::rhi
