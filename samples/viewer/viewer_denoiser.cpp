#include "viewer_denoiser.hpp"

#include <algorithm>
#include <stdexcept>

#include <hush/core/error.hpp>
#include <hush/graph/render_graph.hpp>
#include <hush/passes/chain_file.hpp>
#include <hush/passes/common/tonemap.hpp>
#include <hush/passes/denoise_inputs.hpp>
#include <hush/rhi/vulkan_interop.hpp>

namespace viewer {

using namespace hush;

struct ViewerDenoiser::Impl {
    rhi::Device device;
    passes::PipelineCache pipelines;
    std::map<passes::InputChannel, rhi::Texture> inputs;
    std::vector<passes::InputChannel> available;
    rhi::Texture denoised, noisy;
    rhi::Extent2D size;
    std::shared_ptr<passes::FrameCamera> camera = std::make_shared<passes::FrameCamera>();
    std::unique_ptr<graph::RenderGraph> graph;

    explicit Impl(rhi::Device d) : device(std::move(d)), pipelines(device) {}
    void build(passes::Chain& chain);
    bool isAvailable(passes::InputChannel c) const {
        return std::find(available.begin(), available.end(), c) != available.end();
    }
};

namespace {

// hush's errors become the viewer's, with the same text.
template <class F> auto translated(F&& f) {
    try {
        return f();
    } catch (const hush::Error& e) {
        throw std::runtime_error(e.what());
    }
}

rhi::Texture wrap(const rhi::Device& device, EngineImageRef image, rhi::Format format, rhi::TextureUsage usage,
                  const std::string& label) {
    return rhi::wrapVulkanImage(device, image.image, {.label = label, .size = {image.width, image.height}, .format = format, .usage = usage});
}

constexpr graph::ImportDesc kEngineInput{.initialState = rhi::ResourceState::SampledRead,
                                         .finalState = rhi::ResourceState::SampledRead};
constexpr graph::ImportDesc kEngineDisplay{.initialState = rhi::ResourceState::CopySrc,
                                           .finalState = rhi::ResourceState::CopySrc};

} // namespace

ViewerDenoiser::ViewerDenoiser(const EngineHandles& e) {
    impl_ = translated([&] {
        return std::make_unique<Impl>(rhi::importVulkanDevice({.instance = e.instance,
                                                               .physicalDevice = e.physicalDevice,
                                                               .device = e.device,
                                                               .queue = e.queue,
                                                               .queueFamilyIndex = e.queueFamily,
                                                               .getInstanceProcAddr = vkGetInstanceProcAddr,
                                                               .label = "viewer",
                                                               .shaderStorageImageExtendedFormats = e.extendedStorageFormats}));
    });
}

ViewerDenoiser::~ViewerDenoiser() = default;

std::vector<LayerLayout> ViewerDenoiser::inputLayouts() {
    std::vector<LayerLayout> layouts;
    for (const auto& info : passes::allInputChannels())
        layouts.push_back({std::string(info.name), rhi::formatInfo(info.format).channels});
    return layouts;
}

VkFormat ViewerDenoiser::inputFormat(const std::string& layer) {
    const auto channel = passes::parseInputChannel(layer);
    if (!channel) throw std::runtime_error("'" + layer + "' is not an input layer of hush");
    return rhi::vulkanFormat(passes::inputChannelInfo(*channel).format);
}

void ViewerDenoiser::setImages(const std::map<std::string, EngineImageRef>& inputs, const std::vector<std::string>& available,
                               EngineImageRef denoised, EngineImageRef noisy) {
    translated([&] {
        using U = rhi::TextureUsage;
        impl_->inputs.clear();
        for (const auto& [name, image] : inputs) {
            const auto channel = *passes::parseInputChannel(name);
            impl_->inputs[channel] = wrap(impl_->device, image, passes::inputChannelInfo(channel).format,
                                          U::TextureBinding | U::StorageBinding | U::CopyDst | U::CopySrc, "engine." + name);
        }
        impl_->available.clear();
        for (const std::string& name : available) impl_->available.push_back(*passes::parseInputChannel(name));
        impl_->denoised = wrap(impl_->device, denoised, rhi::Format::RGBA32Float, U::CopyDst | U::CopySrc, "engine.denoised");
        impl_->noisy = wrap(impl_->device, noisy, rhi::Format::RGBA32Float, U::CopyDst | U::CopySrc, "engine.noisy");
        impl_->size = {denoised.width, denoised.height};
        return 0;
    });
}

void ViewerDenoiser::releaseImages() {
    impl_->graph.reset();
    impl_->inputs.clear();
    impl_->denoised = {};
    impl_->noisy = {};
}

void ViewerDenoiser::Impl::build(passes::Chain& chain) {
    graph = std::make_unique<graph::RenderGraph>(device, graph::RenderGraphDesc{.label = "viewer." + chain.name()});
    graph->setOutputSize(size);
    passes::DenoiseInputs in;
    in.camera = camera;
    // What the chain reads, and those of its optional inputs the frames carry.
    std::vector<passes::InputChannel> read = chain.inputs();
    for (auto c : chain.optionalInputs())
        if (isAvailable(c)) read.push_back(c);
    read.push_back(passes::InputChannel::Color);   // the noisy side of the side-by-side view
    for (auto c : read)
        if (!in.has(c)) in[c] = graph->importTexture("input." + std::string(passes::inputChannelInfo(c).name), inputs.at(c), kEngineInput);
    passes::NodeContext ctx{*graph, pipelines};
    const passes::ChainOutputs out = chain.build(ctx, in);
    const auto noisyDisplay = passes::addTonemapPass(ctx, "viewer.noisy", in[passes::InputChannel::Color]);
    const auto denoisedTarget = graph->importTexture("engine.denoised", denoised, kEngineDisplay);
    const auto noisyTarget = graph->importTexture("engine.noisy", noisy, kEngineDisplay);
    struct Copies {
        graph::TextureHandle denoised, noisy;
    };
    // The engine's display images are written by copies, so they need no storage usage.
    const Copies copies = graph->addPass<Copies>("viewer.present", [&](graph::PassBuilder& b, Copies& c) {
        const auto fromDenoised = b.copyFrom("denoised_display", out.display);
        const auto fromNoisy = b.copyFrom("noisy_display", noisyDisplay);
        c.denoised = b.copyTo("engine_denoised", denoisedTarget);
        c.noisy = b.copyTo("engine_noisy", noisyTarget);
        return [=, denoised = c.denoised, noisy = c.noisy](graph::PassContext& pc) {
            pc.encoder().copyTextureToTexture({.texture = pc.texture(fromDenoised)}, {.texture = pc.texture(denoised)});
            pc.encoder().copyTextureToTexture({.texture = pc.texture(fromNoisy)}, {.texture = pc.texture(noisy)});
        };
    });
    graph->markOutput(copies.denoised);
    graph->markOutput(copies.noisy);
    graph->compile();
}

void ViewerDenoiser::setChain(const std::string& chain) {
    translated([&] {
        auto made = chain.starts_with("{") ? passes::parseChainJson(chain, "viewer knob") : passes::makeChain(chain);
        // A missing emission layer is zeros (nothing to separate); any other is an error.
        for (auto c : made->inputs())
            if (!impl_->isAvailable(c) && c != passes::InputChannel::Emission)
                throw Error(ErrorKind::NotFound, "chain '" + made->name() + "' reads '" +
                                                     std::string(passes::inputChannelInfo(c).name) + "', which the frames lack");
        if (impl_->graph) impl_->graph->waitIdle();
        impl_->build(*made);
        chainName_ = made->name();
        return 0;
    });
}

void ViewerDenoiser::setCamera(const CameraMatrices& c) {
    auto& camera = *impl_->camera;
    std::copy_n(c.view, 16, camera.view.begin());
    std::copy_n(c.projection, 16, camera.projection.begin());
    std::copy_n(c.previousView, 16, camera.previousView.begin());
    std::copy_n(c.previousProjection, 16, camera.previousProjection.begin());
    std::copy_n(c.position, 3, camera.position.begin());
    camera.metresPerUnit = c.metresPerUnit;
}

void ViewerDenoiser::record(VkCommandBuffer commandBuffer) {
    translated([&] {
        rhi::CommandEncoder encoder = rhi::encodeIntoVulkanCommandBuffer(impl_->device, commandBuffer);
        impl_->graph->record(encoder);
        encoder.finish();
        return 0;
    });
}

void ViewerDenoiser::frameCompleted() {
    translated([&] {
        impl_->graph->frameCompleted();
        return 0;
    });
}

std::vector<PassTime> ViewerDenoiser::passTimes() const {
    std::vector<PassTime> times;
    for (const auto& pass : impl_->graph->timings().passes) times.push_back({pass.name, pass.gpuMs});
    return times;
}

double ViewerDenoiser::frameMs() const {
    const auto& t = impl_->graph->timings();
    return t.valid ? t.totalGpuMs : -1.0;
}

} // namespace viewer
