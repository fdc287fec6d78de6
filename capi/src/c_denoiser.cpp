// The C API's denoiser (hush.h): a ChainRunner behind an opaque handle, with every
// argument checked and named before it reaches the library.
#include <algorithm>
#include <cstring>
#include <string>

#include <hush/core/arguments.hpp>
#include <hush/passes/chain_file.hpp>

#include "c_api_guard.hpp"
#include "c_objects.hpp"

using namespace hush;
using capi::badArgument;
using capi::guarded;
using capi::required;

namespace hush::capi {

passes::InputChannel denoiserInput(const HushDenoiser_T& denoiser, const char* name) {
    required(name, "name");
    const auto channel = passes::parseInputChannel(name);
    if (channel && std::find(denoiser.inputs.begin(), denoiser.inputs.end(), *channel) != denoiser.inputs.end())
        return *channel;
    std::string list;
    for (auto c : denoiser.inputs) list += std::string(list.empty() ? "" : ", ") + std::string(passes::inputChannelInfo(c).name);
    badArgument("name", std::string("'") + name + "' is not an input of chain '" + denoiser.runner->chain().name() +
                            "' (its inputs: " + list + ")");
}

} // namespace hush::capi

namespace {

std::unique_ptr<passes::Chain> chainOf(const HushDenoiserDesc& desc) {
    if (desc.chain && desc.chainJson) badArgument("desc->chain", "and 'desc->chainJson' are both set; set one");
    if (desc.chainJson) return passes::parseChainJson(desc.chainJson, "chainJson");   // errors read "chainJson:<line>:<column>"; the chain is named "chainJson" unless it says "name"
    if (!desc.chain) badArgument("desc->chain", "is NULL and so is 'desc->chainJson'; name a built-in chain or give a chain file's text");
    auto chain = passes::makeBuiltinChain(desc.chain);
    if (!chain) {
        std::string names;
        for (const auto& n : passes::builtinChainNames()) names += (names.empty() ? "" : ", ") + n;
        badArgument("desc->chain", std::string("'") + desc.chain + "' is not a built-in chain (" + names + ")");
    }
    return chain;
}

std::vector<passes::InputChannel> availableOf(const char* available) {
    std::vector<passes::InputChannel> channels;
    if (!available) return channels;
    for (const std::string& name : core::splitList(available)) {
        const auto channel = passes::parseInputChannel(name);
        if (!channel) badArgument("desc->available", "names '" + name + "', which is not a frame-format layer");
        channels.push_back(*channel);
    }
    if (channels.empty()) badArgument("desc->available", "is empty; NULL means every layer");
    return channels;
}

HushDenoiser_T& checkedDenoiser(HushDenoiser denoiser) { return *required(denoiser, "denoiser"); }

// Copies rows `rowStrideBytes` apart into one packed image (or returns the caller's).
const float* packed(HushDenoiser_T& d, const float* pixels, uint32_t width, uint32_t height, uint32_t components,
                    size_t rowStrideBytes) {
    const size_t rowBytes = size_t(width) * components * sizeof(float);
    if (rowStrideBytes == 0 || rowStrideBytes == rowBytes) return pixels;
    if (rowStrideBytes < rowBytes || rowStrideBytes % sizeof(float) != 0)
        badArgument("rowStrideBytes", "is " + std::to_string(rowStrideBytes) + ", less than a row (" +
                                          std::to_string(rowBytes) + " bytes) or not a multiple of 4");
    d.staging.resize(size_t(width) * height * components);
    for (uint32_t y = 0; y < height; ++y)
        std::memcpy(d.staging.data() + size_t(y) * width * components,
                    reinterpret_cast<const char*>(pixels) + y * rowStrideBytes, rowBytes);
    return d.staging.data();
}

} // namespace

extern "C" {

HUSH_API HushStatus hushCreateDenoiser(HushContext context, const HushDenoiserDesc* desc, HushDenoiser* denoiser) {
    return guarded("hushCreateDenoiser", [&] {
        required(denoiser, "denoiser");
        *denoiser = nullptr;
        required(context, "context");
        required(desc, "desc");
        if (desc->width == 0 || desc->height == 0)
            badArgument("desc->width", "and 'desc->height' must be positive (got " + std::to_string(desc->width) + "x" +
                                           std::to_string(desc->height) + ")");
        auto made = std::make_unique<HushDenoiser_T>();
        made->context = context;
        made->runner = std::make_unique<passes::ChainRunner>(context->device, chainOf(*desc),
                                                             rhi::Extent2D{desc->width, desc->height},
                                                             graph::RenderGraphDesc{}, availableOf(desc->available));
        made->inputs = made->runner->inputs().channels();
        *denoiser = made.release();
    });
}

HUSH_API void hushDestroyDenoiser(HushDenoiser denoiser) { delete denoiser; }

HUSH_API uint32_t hushDenoiserInputCount(HushDenoiser denoiser) {
    return denoiser ? uint32_t(denoiser->inputs.size()) : 0;
}

HUSH_API HushStatus hushDenoiserInput(HushDenoiser denoiser, uint32_t index, const char** name, uint32_t* components) {
    return guarded("hushDenoiserInput", [&] {
        HushDenoiser_T& d = checkedDenoiser(denoiser);
        if (index >= d.inputs.size())
            badArgument("index", std::to_string(index) + " is past the " + std::to_string(d.inputs.size()) + " inputs");
        const auto& info = passes::inputChannelInfo(d.inputs[index]);
        if (name) *name = info.name.data();   // the table's names are NUL-terminated literals
        if (components) *components = info.components;
    });
}

HUSH_API HushStatus hushSetInput(HushDenoiser denoiser, const char* name, const float* pixels, uint32_t width,
                                 uint32_t height, uint32_t components, size_t rowStrideBytes) {
    return guarded("hushSetInput", [&] {
        HushDenoiser_T& d = checkedDenoiser(denoiser);
        const passes::InputChannel channel = capi::denoiserInput(d, name);
        required(pixels, "pixels");
        const auto& info = passes::inputChannelInfo(channel);
        const auto size = d.runner->inputs().size();
        if (width != size.width || height != size.height)
            badArgument("width", "and 'height' are " + std::to_string(width) + "x" + std::to_string(height) +
                                     " for input '" + name + "'; the denoiser is " + std::to_string(size.width) + "x" +
                                     std::to_string(size.height));
        if (components != info.components)
            badArgument("components", "is " + std::to_string(components) + " for input '" + name + "', which has " +
                                          std::to_string(info.components));
        const float* data = packed(d, pixels, width, height, components, rowStrideBytes);
        d.runner->inputs().upload(channel, {data, size_t(width) * height * components}, components);
        d.set[size_t(channel)] = true;
    });
}

HUSH_API HushStatus hushSetCamera(HushDenoiser denoiser, const HushCamera* camera) {
    return guarded("hushSetCamera", [&] {
        HushDenoiser_T& d = checkedDenoiser(denoiser);
        required(camera, "camera");
        passes::FrameCamera c;
        std::copy_n(camera->view, 16, c.view.begin());
        std::copy_n(camera->projection, 16, c.projection.begin());
        std::copy_n(camera->previousView, 16, c.previousView.begin());
        std::copy_n(camera->previousProjection, 16, c.previousProjection.begin());
        std::copy_n(camera->position, 3, c.position.begin());
        c.metresPerUnit = camera->metresPerUnit == 0.0f ? 1.0f : camera->metresPerUnit;
        d.runner->inputs().setCamera(c);   // validates, naming the field
    });
}

HUSH_API HushStatus hushExecute(HushDenoiser denoiser) {
    return guarded("hushExecute", [&] {
        HushDenoiser_T& d = checkedDenoiser(denoiser);
        for (auto channel : d.inputs)
            if (!d.set[size_t(channel)])
                throw Error(ErrorKind::NotFound, "input '" + std::string(passes::inputChannelInfo(channel).name) +
                                                     "' was never set (hushSetInput or hushSetInputVulkanImage)");
        d.runner->run();
        d.executed = true;
    });
}

HUSH_API HushStatus hushResetHistory(HushDenoiser denoiser) {
    return guarded("hushResetHistory", [&] { checkedDenoiser(denoiser).runner->resetHistory(); });
}

HUSH_API HushStatus hushReadOutput(HushDenoiser denoiser, HushOutput output, float* rgba, size_t count) {
    return guarded("hushReadOutput", [&] {
        HushDenoiser_T& d = checkedDenoiser(denoiser);
        required(rgba, "rgba");
        if (output != HUSH_OUTPUT_RADIANCE && output != HUSH_OUTPUT_DISPLAY)
            badArgument("output", "is " + std::to_string(int(output)) + ", not HUSH_OUTPUT_RADIANCE or HUSH_OUTPUT_DISPLAY");
        if (!d.executed) throw Error(ErrorKind::InvalidArgument, "no frame was executed yet (hushExecute)");
        const auto size = d.runner->inputs().size();
        const size_t needed = size_t(size.width) * size.height * 4;
        if (count < needed)
            badArgument("count", "is " + std::to_string(count) + "; the output needs " + std::to_string(needed) + " floats");
        const std::vector<float> values = output == HUSH_OUTPUT_DISPLAY ? d.runner->readDisplay() : d.runner->readRadiance();
        std::copy(values.begin(), values.end(), rgba);
    });
}

// Read straight from the graph's timings: run() waits, so they are the last frame's.
HUSH_API uint32_t hushPassCount(HushDenoiser denoiser) {
    return denoiser && denoiser->executed ? uint32_t(denoiser->runner->graph().timings().passes.size()) : 0;
}

HUSH_API HushStatus hushPassTiming(HushDenoiser denoiser, uint32_t index, const char** name, double* gpuMs) {
    return guarded("hushPassTiming", [&] {
        HushDenoiser_T& d = checkedDenoiser(denoiser);
        const uint32_t count = hushPassCount(denoiser);
        if (index >= count)
            badArgument("index", std::to_string(index) + " is past the " + std::to_string(count) + " timed passes");
        const auto& pass = d.runner->graph().timings().passes[index];
        if (name) *name = pass.name.c_str();
        if (gpuMs) *gpuMs = pass.gpuMs;
    });
}

HUSH_API double hushFrameGpuMs(HushDenoiser denoiser) {
    if (!denoiser || !denoiser->executed) return -1.0;
    const auto& timings = denoiser->runner->graph().timings();
    return timings.valid ? timings.totalGpuMs : -1.0;
}

} // extern "C"
