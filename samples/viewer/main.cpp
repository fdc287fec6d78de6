// hush-viewer: a minimal engine that owns Vulkan (instance, device, queue, images,
// command buffers, fences, a GLFW window and swapchain) and denoises with hush the way
// an integrator would: hush imports its device and images and records the chain into
// the engine's own command buffer, between the engine's upload and present passes.
// docs/integration.md walks through it.
//
//   hush-viewer --in <frames> [--chain svgf] [--validation]          a window
//   hush-viewer --in <frames> --headless --frames N --out <folder>   no window
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "engine_vulkan.hpp"
#include "frame_files.hpp"
#include "viewer_denoiser.hpp"
#include "viewer_engine.hpp"
#ifdef HUSH_VIEWER_WINDOW
#include "viewer_window.hpp"
#endif

namespace viewer {
namespace {

constexpr const char* kUsage =
    "usage: hush-viewer --in <folder> [--chain <name|file>] [--first <i>] [--frames <n>]\n"
    "                   [--headless --out <folder>] [--scale <k>] [--validation] [--adapter <text>]\n"
    "\n"
    "A minimal engine that owns Vulkan and a window and runs a hush chain inside its own\n"
    "frame: it uploads each frame's G-buffer and noisy radiance from <folder> (tracer\n"
    "frames standing in for its raster and ray passes) into its own images, records the\n"
    "chain into its own command buffer, and blits hush's output into its swapchain.\n"
    "\n"
    "  --chain <c>     eaw, svgf (default), bmfr, mara, rdae, or a chain file\n"
    "  --frames <n>    frames to run (headless; default: each frame once); windowed, the\n"
    "                  sequence loops\n"
    "  --headless      no window: write each displayed frame to --out as frame_<i>.exr\n"
    "                  (the display image's rgb in the color layer, 32-bit float)\n"
    "  --scale <k>     window size as a multiple of the frame size (default 2)\n"
    "  --validation    Vulkan validation with synchronization validation; any message\n"
    "                  makes the exit status 1\n"
    "keys: 1-5 chain (eaw, svgf, bmfr, mara, rdae), S split screen with the noisy input,\n"
    "      + / - a-trous iterations (eaw, svgf), Q or Esc quit. The title shows GPU ms.\n";

const char* kChainKeys[] = {"eaw", "svgf", "bmfr", "mara", "rdae"};

struct Options {
    std::string in, out, chain = "svgf", adapter;
    uint32_t first = 0, frames = 0, scale = 2;
    bool headless = false, validation = false;
};

uint32_t number(const std::string& text, const char* option) {
    char* end = nullptr;
    const unsigned long value = std::strtoul(text.c_str(), &end, 10);
    if (text.empty() || *end || value > 100000) throw std::runtime_error(std::string(option) + ": '" + text + "' is not a count");
    return uint32_t(value);
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw std::runtime_error(arg + " needs a value");
            return argv[++i];
        };
        if (arg == "--in") o.in = value();
        else if (arg == "--out") o.out = value();
        else if (arg == "--chain") o.chain = value();
        else if (arg == "--adapter") o.adapter = value();
        else if (arg == "--first") o.first = number(value(), "--first");
        else if (arg == "--frames") o.frames = number(value(), "--frames");
        else if (arg == "--scale") o.scale = std::max(1u, number(value(), "--scale"));
        else if (arg == "--headless") o.headless = true;
        else if (arg == "--validation") o.validation = true;
        else if (arg == "--help" || arg == "-h") std::fputs(kUsage, stdout), std::exit(0);
        else throw std::runtime_error("unknown argument '" + arg + "' (hush-viewer --help)");
    }
    if (o.in.empty()) throw std::runtime_error("--in <folder of frames> is required (hush render writes them)");
    if (o.headless && o.out.empty()) throw std::runtime_error("--headless needs --out <folder>");
    if (const char* adapter = std::getenv("HUSH_ADAPTER"); o.adapter.empty() && adapter) o.adapter = adapter;
    return o;
}

std::map<std::string, VkFormat> formatsOf(const std::vector<LayerLayout>& layers) {
    std::map<std::string, VkFormat> formats;
    for (const LayerLayout& layer : layers) formats[layer.name] = ViewerDenoiser::inputFormat(layer.name);
    return formats;
}

// The engine's images, handed to hush; what the frames carry, plus emission (zeros
// when absent: nothing to separate).
void connect(ViewerDenoiser& denoiser, const ViewerEngine& engine, const FrameSource& source) {
    std::map<std::string, EngineImageRef> inputs;
    for (const auto& [name, image] : engine.inputs()) inputs[name] = {image.image, image.width, image.height};
    std::vector<std::string> available = source.present();
    available.push_back("emission");
    denoiser.setImages(inputs, available, {engine.denoised().image, engine.width(), engine.height()},
                       {engine.noisy().image, engine.width(), engine.height()});
}

int runHeadless(const Options& o, EngineVulkan& vulkan, const FrameSource& source) {
    const auto layers = ViewerDenoiser::inputLayouts();
    ViewerEngine engine(vulkan, source.width(), source.height(), layers, formatsOf(layers), ViewerDenoiser::kDisplayFormat, 1);
    ViewerDenoiser denoiser({vulkan.instance(), vulkan.physicalDevice(), vulkan.device(), vulkan.queue(),
                             vulkan.queueFamily(), vulkan.extendedStorageFormats()});
    connect(denoiser, engine, source);
    denoiser.setChain(o.chain);
    std::filesystem::create_directories(o.out);
    const uint32_t frames = o.frames ? o.frames : uint32_t(source.frames().size());
    for (uint32_t f = 0; f < frames; ++f) {
        const SourceFrame& frame = source.frames()[f % source.frames().size()];
        FrameSlot& slot = engine.slot(f);
        engine.begin(slot);
        engine.recordUpload(slot, frame);              // the engine's pass
        denoiser.setCamera(frame.camera);
        denoiser.record(slot.commands);                // hush, in the engine's command buffer
        engine.recordReadback(slot);                   // the engine's pass
        engine.submit(slot);
        engine.waitIdle();
        denoiser.frameCompleted();
        writeDisplayFrame(o.out, f, engine.width(), engine.height(), static_cast<const float*>(slot.readback.mapped));
        std::printf("frame %u/%u: %s %.3f GPU ms\n", f + 1, frames, denoiser.chainName().c_str(), denoiser.frameMs());
    }
    return 0;
}

#ifdef HUSH_VIEWER_WINDOW
std::string titleOf(const ViewerDenoiser& denoiser, bool sideBySide, uint32_t width, uint32_t height) {
    std::string title = "hush viewer: " + denoiser.chainName() + " at " + std::to_string(width) + "x" +
                        std::to_string(height) + (sideBySide ? " (left half: noisy input)" : "");
    char ms[64];
    std::snprintf(ms, sizeof ms, " | %.2f GPU ms:", denoiser.frameMs());
    title += ms;
    auto times = denoiser.passTimes();
    std::sort(times.begin(), times.end(), [](const PassTime& a, const PassTime& b) { return a.ms > b.ms; });
    for (size_t i = 0; i < times.size() && i < 3; ++i) {
        std::snprintf(ms, sizeof ms, " %s %.2f", times[i].name.c_str(), times[i].ms);
        title += ms;
    }
    return title + " | 1-5 chain, S split screen, +/- iterations";
}

std::string withIterations(const std::string& chain, int iterations) {
    return "{\"name\": \"" + chain + "\", \"base\": \"" + chain + "\", \"settings\": {\"atrous\": {\"iterations\": " +
           std::to_string(iterations) + "}}}";
}

// What the engine renders at its current resolution: its images and the frames at
// that size. A window resize makes a new one (the render resolution follows the
// window), and hush recompiles its graph over the new images (the history restarts).
struct Resolution {
    std::unique_ptr<ViewerEngine> engine;
    std::vector<SourceFrame> frames;
};

Resolution renderAt(EngineVulkan& vulkan, const FrameSource& source, VkExtent2D size, uint32_t slots) {
    const auto layers = ViewerDenoiser::inputLayouts();
    Resolution r;
    r.engine = std::make_unique<ViewerEngine>(vulkan, size.width, size.height, layers, formatsOf(layers),
                                              ViewerDenoiser::kDisplayFormat, slots);
    for (const SourceFrame& frame : source.frames())
        r.frames.push_back(size.width == source.width() && size.height == source.height()
                               ? frame
                               : resampled(frame, source.width(), source.height(), size.width, size.height, layers));
    return r;
}

int runWindow(const Options& o, ViewerWindow& window, EngineVulkan& vulkan, const FrameSource& source) {
    constexpr uint32_t kSlots = 2;
    Resolution at = renderAt(vulkan, source, {source.width(), source.height()}, kSlots);
    ViewerDenoiser denoiser({vulkan.instance(), vulkan.physicalDevice(), vulkan.device(), vulkan.queue(),
                             vulkan.queueFamily(), vulkan.extendedStorageFormats()});
    connect(denoiser, *at.engine, source);
    std::string chain = o.chain;   // what setChain was last given
    denoiser.setChain(chain);
    std::vector<VkSemaphore> available(kSlots);
    for (VkSemaphore& s : available) {
        VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
        check(vkCreateSemaphore(vulkan.device(), &info, nullptr, &s), "vkCreateSemaphore");
    }
    bool sideBySide = false;
    int iterations = 5;
    uint64_t frame = 0;
    const auto settle = [&] {   // every hush frame in flight reported, before the graph changes
        at.engine->waitIdle();
        for (uint32_t k = 0; k < kSlots; ++k)
            if (at.engine->slot(frame + k).hushPending)
                denoiser.frameCompleted(), at.engine->slot(frame + k).hushPending = false;
    };
    const auto switchTo = [&](const std::string& next) {
        settle();
        denoiser.setChain(next);
        chain = next;
    };
    while (!window.shouldClose() && (o.frames == 0 || frame < o.frames)) {
        const WindowRequests requests = window.poll();
        if (requests.chain >= 0 && requests.chain < 5) switchTo(kChainKeys[requests.chain]);
        if (requests.knob && (denoiser.chainName() == "svgf" || denoiser.chainName() == "eaw")) {
            iterations = std::clamp(iterations + requests.knob, 0, 16);
            switchTo(withIterations(denoiser.chainName(), iterations));
        }
        if (requests.toggleSideBySide) sideBySide = !sideBySide;
        if (requests.resized) {
            settle();
            window.rebuild();
            const VkExtent2D w = window.framebufferSize();
            const VkExtent2D size{std::max(8u, w.width / o.scale), std::max(8u, w.height / o.scale)};
            if (size.width != at.engine->width() || size.height != at.engine->height()) {
                denoiser.releaseImages();   // hush lets go of the old images before the engine frees them
                at = {};
                at = renderAt(vulkan, source, size, kSlots);
                connect(denoiser, *at.engine, source);
                denoiser.setChain(chain);   // recompiled for the new size; the history starts over
            }
        }
        ViewerEngine& engine = *at.engine;
        FrameSlot& slot = engine.slot(frame);
        const VkSemaphore acquired = available[frame % kSlots];
        engine.begin(slot);   // waits for this slot's last submission
        if (slot.hushPending) denoiser.frameCompleted(), slot.hushPending = false;
        uint32_t image = 0;
        if (!window.acquire(acquired, image)) {
            vkEndCommandBuffer(slot.commands);
            continue;
        }
        const SourceFrame& current = at.frames[frame % at.frames.size()];
        engine.recordUpload(slot, current);
        denoiser.setCamera(current.camera);
        denoiser.record(slot.commands);
        slot.hushPending = true;
        window.recordPresent(slot.commands, image, engine.denoised().image, engine.noisy().image, engine.width(),
                             engine.height(), sideBySide);
        engine.submit(slot, acquired, VK_PIPELINE_STAGE_2_TRANSFER_BIT, window.renderFinished(image));
        window.present(image);
        if (frame % 8 == 0) window.setTitle(titleOf(denoiser, sideBySide, engine.width(), engine.height()));
        ++frame;
    }
    settle();
    for (VkSemaphore s : available) vkDestroySemaphore(vulkan.device(), s, nullptr);
    return 0;
}
#endif

int run(const Options& o) {
    const FrameSource source(o.in, o.first, o.headless ? o.frames : 0, ViewerDenoiser::inputLayouts());
    std::printf("hush-viewer: %zu frame(s) of %s, %ux%u, chain %s\n", source.frames().size(), o.in.c_str(),
                source.width(), source.height(), o.chain.c_str());
    EngineOptions engineOptions{.validation = o.validation, .adapter = o.adapter};
    int status = 0;
    if (o.headless) {
        EngineVulkan vulkan(engineOptions);
        std::printf("adapter: %s\n", vulkan.adapterName().c_str());
        status = runHeadless(o, vulkan, source);
    } else {
#ifdef HUSH_VIEWER_WINDOW
        ViewerWindow window(source.width() * o.scale, source.height() * o.scale);
        engineOptions.instanceExtensions = window.instanceExtensions();
        engineOptions.swapchain = true;
        EngineVulkan vulkan(engineOptions);
        std::printf("adapter: %s\n", vulkan.adapterName().c_str());
        window.attach(vulkan);
        status = runWindow(o, window, vulkan, source);
        window.detach();
#else
        throw std::runtime_error("built without GLFW (libglfw3-dev): only --headless is available");
#endif
    }
    if (o.validation && EngineVulkan::validationMessages() != 0) {
        std::fprintf(stderr, "hush-viewer: %zu validation message(s)\n", EngineVulkan::validationMessages());
        return 1;
    }
    return status;
}

} // namespace
} // namespace viewer

int main(int argc, char** argv) {
    try {
        return viewer::run(viewer::parse(argc, argv));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "hush-viewer: %s\n", e.what());
        return 2;
    }
}
