#pragma once
// What every node function takes: the graph it adds passes to and the pipelines it
// may use. A node is a free function `addXxxPass(ctx, name, inputs..., settings)`
// that adds one or more passes named "<name>" or "<name>.<stage>" and returns the
// handles of what it produced. Its ports, its shader's bindings and its chain-file
// ports are one name; its settings' fields and its shader's push constants too
// (docs/passes/README.md, "Writing a node").
#include <hush/graph/render_graph.hpp>
#include <hush/passes/pipeline_cache.hpp>
#include <hush/rhi/push_constants.hpp>

namespace hush::passes {

struct NodeContext {
    graph::RenderGraph& graph;
    PipelineCache& pipelines;
};

// The texture every node creates unless it says otherwise: full output size, fp32.
// (fp16 would overflow on squared HDR luminance and on 1e6 fireflies; see
// docs/passes/README.md, "Precision".)
inline graph::TextureInfo fullSize(rhi::Format format = rhi::Format::RGBA32Float) {
    return {.format = format, .size = graph::SizeSpec::relative()};
}

} // namespace hush::passes
