#pragma once
// ComputePipelineDesc::constants checked against the shader's reflected
// specialization constants and packed as Vulkan wants them.
#include <string>
#include <vector>

#include <volk.h>

#include <hush/rhi/pipeline.hpp>

namespace hush::rhi::detail {

struct Specialization {
    std::vector<VkSpecializationMapEntry> entries;
    std::vector<uint32_t> data;   // one 32-bit word per entry
    VkSpecializationInfo info{};  // points into entries and data: use it before moving this
};

// Throws hush::Error (InvalidArgument) naming the pipeline and the key: a key the
// shader has no constant for (listing those it has), a key given twice, or a value
// its type cannot hold exactly.
Specialization specialize(const std::string& pipeline, const ShaderReflection& reflection,
                          const std::vector<ConstantEntry>& constants);

} // namespace hush::rhi::detail
