#include "graph/graph_test_util.hpp"

namespace hush::graph_test {

using namespace hush::graph;

rhi::ComputePipeline makePipeline(const rhi::Device& device, std::string_view name) {
    const std::string label = "graph/" + std::string(name);
    auto module = device.createShaderModule({.label = label, .code = graph_test_shaders::find(name)});
    return device.createComputePipeline({.label = label, .module = module});
}

Pipelines makePipelines(const rhi::Device& device) {
    return {makePipeline(device, "fill"), makePipeline(device, "combine"), makePipeline(device, "copy"),
            makePipeline(device, "accumulate")};
}

std::vector<uint32_t> fillImage(uint32_t seed, uint32_t width, uint32_t height) {
    std::vector<uint32_t> out(size_t(width) * height);
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) out[size_t(y) * width + x] = fillReference(seed, x, y);
    return out;
}

rhi::Texture makeTexture(const std::string& label, uint32_t width, uint32_t height, const rhi::Device& device) {
    using rhi::TextureUsage;
    return device.createTexture(
        {.label = label,
         .size = {width, height},
         .format = kFormat,
         .usage = TextureUsage::StorageBinding | TextureUsage::CopySrc | TextureUsage::CopyDst});
}

void upload(const rhi::Texture& texture, const std::vector<uint32_t>& values, ResourceState before, ResourceState after,
            const rhi::Device& device) {
    device.queue().writeTexture({.texture = texture, .data = test::bytesOf(values), .before = before, .after = after});
}

std::vector<uint32_t> download(const rhi::Texture& texture, ResourceState state, const rhi::Device& device) {
    return test::valuesOf<uint32_t>(device.queue().readTexture({.texture = texture, .state = state}));
}

std::vector<uint32_t> readOutput(const RenderGraph& graph, TextureHandle output, const rhi::Device& device) {
    return download(graph.outputTexture(output), graph.outputState(output), device);
}

rhi::PushConstants combineParams(const rhi::ComputePipeline& combine, const CombineParams& p) {
    rhi::PushConstants params(combine);
    params.set("mulA", p.mulA).set("mulB", p.mulB).set("add", p.add).set("rotate", p.rotate);
    return params;
}

TextureHandle addFill(RenderGraph& graph, const Pipelines& pipelines, const std::string& name, uint32_t seed,
                      SizeSpec size) {
    const auto pipeline = pipelines.fill;
    rhi::PushConstants params(pipeline);
    params.set("seed", seed);
    struct Out {
        TextureHandle dst;
    };
    return graph
        .addPass<Out>(name,
                      [&](PassBuilder& b, Out& o) {
                          o.dst = b.write("dst", b.create(name, {.format = kFormat, .size = size}));
                          const auto group = b.bindGroup(pipeline);
                          return [=](PassContext& ctx) { ctx.dispatch(pipeline, group, ctx.texture(o.dst).size(), params); };
                      })
        .dst;
}

TextureHandle addCombine(RenderGraph& graph, const Pipelines& pipelines, const std::string& name, TextureHandle a,
                         TextureHandle b, const CombineParams& combine, SizeSpec size) {
    const auto pipeline = pipelines.combine;
    const auto params = combineParams(pipeline, combine);
    struct Out {
        TextureHandle dst;
    };
    return graph
        .addPass<Out>(name,
                      [&](PassBuilder& builder, Out& o) {
                          builder.read("a", a);
                          builder.read("b", b);
                          o.dst = builder.write("dst", builder.create(name, {.format = kFormat, .size = size}));
                          const auto group = builder.bindGroup(pipeline);
                          return [=](PassContext& ctx) { ctx.dispatch(pipeline, group, ctx.texture(o.dst).size(), params); };
                      })
        .dst;
}

namespace {

TextureHandle addCopyPass(RenderGraph& graph, const rhi::ComputePipeline& pipeline, const std::string& name,
                          TextureHandle src, TextureHandle dst, const std::string& createName, SizeSpec size,
                          uint32_t add) {
    rhi::PushConstants params(pipeline);
    params.set("add", add);
    struct Out {
        TextureHandle dst;
    };
    return graph
        .addPass<Out>(name,
                      [&](PassBuilder& b, Out& o) {
                          b.read("src", src);
                          o.dst = b.write("dst", dst.valid() ? dst : b.create(createName, {.format = kFormat, .size = size}));
                          const auto group = b.bindGroup(pipeline);
                          return [=](PassContext& ctx) { ctx.dispatch(pipeline, group, ctx.texture(o.dst).size(), params); };
                      })
        .dst;
}

} // namespace

TextureHandle addCopy(RenderGraph& graph, const Pipelines& pipelines, const std::string& name, TextureHandle src,
                      uint32_t add, SizeSpec size) {
    return addCopyPass(graph, pipelines.copy, name, src, {}, name, size, add);
}

TextureHandle addCopyInto(RenderGraph& graph, const Pipelines& pipelines, const std::string& name, TextureHandle src,
                          TextureHandle dst, uint32_t add) {
    return addCopyPass(graph, pipelines.copy, name, src, dst, {}, {}, add);
}

} // namespace hush::graph_test
