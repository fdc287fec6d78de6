#pragma once
// PipelineCache: the compute pipelines of hush's built-in shaders (shaders/<method>/
// <node>.comp), made once per device and shared by every node of every chain built
// with the cache, so that building a second chain (or rebuilding one after a size
// change) compiles nothing again.
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <hush/rhi/device.hpp>
#include <hush/rhi/pipeline.hpp>

namespace hush::passes {

class PipelineCache {
public:
    explicit PipelineCache(rhi::Device device) : device_(std::move(device)) {}
    // The pipeline (a ref-counted handle: copy it into execute lambdas) of the embedded shader `name` ("svgf/atrous"), layout reflected.
    // Throws hush::Error (NotFound) listing the shaders when there is no such shader.
    const rhi::ComputePipeline& get(std::string_view name);
    // The same shader with specialization constants set (rhi::ComputePipelineDesc::
    // constants): one pipeline per distinct list, so that nodes with equal settings share it.
    const rhi::ComputePipeline& get(std::string_view name, const std::vector<rhi::ConstantEntry>& constants);
    const rhi::Device& device() const { return device_; }

private:
    rhi::Device device_;
    std::map<std::string, rhi::ComputePipeline, std::less<>> pipelines_;
};

} // namespace hush::passes
