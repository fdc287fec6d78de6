#include "graph/graph_test_util.hpp"

namespace hush::graph_test {

using namespace hush::graph;

namespace {

rhi::ComputePipeline makePipeline(const rhi::Device& device, std::string_view name) {
    const std::string label = "graph/" + std::string(name);
    auto module = device.createShaderModule({.label = label, .code = graph_test_shaders::find(name)});
    return device.createComputePipeline({.label = label, .module = module});
}

} // namespace

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

TextureHandle addFill(RenderGraph& graph, const Pipelines& pipelines, const std::string& name, uint32_t seed,
                      SizeSpec size) {
    TextureHandle result;
    const auto pipeline = pipelines.fill;
    graph.addPass(name, [&](PassBuilder& b) {
        auto dst = b.write("dst", b.create(name, {.format = kFormat, .size = size}));
        auto group = b.bindGroup(pipeline, 0, {{.name = "dst", .texture = dst}});
        result = dst;
        return [=](PassContext& ctx) {
            const auto extent = ctx.texture(dst).size();
            ctx.dispatch(pipeline, group, extent, seed);
        };
    });
    return result;
}

TextureHandle addCombine(RenderGraph& graph, const Pipelines& pipelines, const std::string& name, TextureHandle a,
                         TextureHandle b, const CombineParams& params, SizeSpec size) {
    TextureHandle result;
    const auto pipeline = pipelines.combine;
    graph.addPass(name, [&](PassBuilder& builder) {
        auto srcA = builder.read("a", a);
        auto srcB = b == a ? srcA : builder.read("b", b);
        auto dst = builder.write("dst", builder.create(name, {.format = kFormat, .size = size}));
        auto group = builder.bindGroup(
            pipeline, 0,
            {{.name = "srcA", .texture = srcA}, {.name = "srcB", .texture = srcB}, {.name = "dst", .texture = dst}});
        result = dst;
        return [=](PassContext& ctx) {
            const auto extent = ctx.texture(dst).size();
            ctx.dispatch(pipeline, group, extent, params);
        };
    });
    return result;
}

namespace {

TextureHandle addCopyPass(RenderGraph& graph, const rhi::ComputePipeline& pipeline, const std::string& name,
                          TextureHandle src, TextureHandle dst, const std::string& createName, SizeSpec size,
                          uint32_t add) {
    TextureHandle result;
    graph.addPass(name, [&](PassBuilder& b) {
        auto in = b.read("src", src);
        auto target = dst.valid() ? dst : b.create(createName, {.format = kFormat, .size = size});
        auto out = b.write("dst", target);
        auto group = b.bindGroup(pipeline, 0, {{.name = "src", .texture = in}, {.name = "dst", .texture = out}});
        result = out;
        return [=](PassContext& ctx) {
            const auto extent = ctx.texture(out).size();
            ctx.dispatch(pipeline, group, extent, add);
        };
    });
    return result;
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
