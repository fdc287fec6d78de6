#include <hush/passes/pipeline_cache.hpp>

#include <hush/shaders/shaders.hpp>

namespace hush::passes {

const rhi::ComputePipeline& PipelineCache::get(std::string_view name) {
    if (auto it = pipelines_.find(name); it != pipelines_.end()) return it->second;
    const std::string label(name);
    auto module = device_.createShaderModule({.label = label, .code = shaders::find(name)});
    auto pipeline = device_.createComputePipeline({.label = label, .module = module});
    return pipelines_.emplace(label, std::move(pipeline)).first->second;
}

} // namespace hush::passes
