#pragma once
// What every node function takes: the graph it adds passes to and the pipelines it
// may use. A node is a free function `addXxxPass(ctx, name, inputs..., settings)`
// that adds one or more passes named "<name>" or "<name>.<stage>" and returns the
// handles of what it produced.
#include <hush/graph/render_graph.hpp>
#include <hush/passes/pipeline_cache.hpp>

namespace hush::passes {

struct NodeContext {
    graph::RenderGraph& graph;
    PipelineCache& pipelines;
};

// The texture every node creates unless it says otherwise: full output size, fp32.
// (fp16 would overflow on squared HDR luminance and on 1e6 fireflies; see
// docs/passes.md, "Precision".)
inline graph::TextureInfo fullSize(rhi::Format format = rhi::Format::RGBA32Float) {
    return {.format = format, .size = graph::SizeSpec::relative()};
}

} // namespace hush::passes
