#include <hush/passes/pipeline_cache.hpp>

#include <cstdio>

#include <hush/shaders/shaders.hpp>

namespace hush::passes {

const rhi::ComputePipeline& PipelineCache::get(std::string_view name) { return get(name, {}); }

const rhi::ComputePipeline& PipelineCache::get(std::string_view name, const std::vector<rhi::ConstantEntry>& constants) {
    // The key spells every constant exactly (%a: the double's bits), in the order given.
    std::string key(name);
    for (const auto& c : constants) {
        char value[64];
        std::snprintf(value, sizeof value, "%a", c.value);
        key += " " + c.key + "=" + value;
    }
    if (auto it = pipelines_.find(key); it != pipelines_.end()) return it->second;
    const std::string label(name);
    auto module = device_.createShaderModule({.label = label, .code = shaders::find(name)});
    auto pipeline = device_.createComputePipeline({.label = label, .module = module, .constants = constants});
    return pipelines_.emplace(key, std::move(pipeline)).first->second;
}

} // namespace hush::passes
