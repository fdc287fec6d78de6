// `hush info`: what Vulkan sees on this machine, and whether compute works on the
// adapter hush would pick. The first thing to run on a new machine or driver.
#include <cstdio>
#include <span>
#include <string>
#include <string_view>

#include <hush/rhi/rhi.hpp>

#include <hush/core/run_environment.hpp>

#include "command.hpp"
#include "graph_selfcheck.hpp"
#include "selfcheck.hpp"

namespace hush::cli {
namespace {

using namespace hush::rhi;

constexpr std::string_view kUsage =
    "usage: hush info [--adapter <text>] [--validation] [--dump-graph <path>]\n"
    "\n"
    "Lists every Vulkan adapter with its type, driver, API version and limits, picks\n"
    "the default adapter, and runs a compute self-check on it (a saxpy on storage\n"
    "buffers and an RGBA32F storage-image kernel, compared with the CPU). Prints\n"
    "PASS or FAIL with the maximum error and the GPU time. Then runs a render-graph\n"
    "self-check: five passes over three frames (one pass culled, one reading a\n"
    "history), compared with the CPU.\n"
    "\n"
    "options:\n"
    "  --adapter <text>  use the first adapter whose name contains <text>\n"
    "                    (default: HUSH_ADAPTER, else discrete, integrated, any, CPU)\n"
    "  --validation      enable the Vulkan validation layer (default: HUSH_VALIDATION=1);\n"
    "                    any validation message makes the self-check fail\n"
    "  --dump-graph <path>  write the self-check's compiled graph to <path>.dot\n"
    "                    (Graphviz) and <path>.json\n"
    "\n"
    "exit status: 0 PASS, 1 FAIL, 2 could not run (no Vulkan, no adapter, ...)\n";

std::string mebibytes(uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.0f MiB", double(bytes) / (1024.0 * 1024.0));
    return text;
}

void printRow(std::string_view key, const std::string& value) {
    std::printf("      %-34.*s %s\n", int(key.size()), key.data(), value.c_str());
}

std::string triple(const uint32_t (&v)[3]) {
    return std::to_string(v[0]) + " x " + std::to_string(v[1]) + " x " + std::to_string(v[2]);
}

void printAdapter(const Adapter& adapter, bool isSelected) {
    const AdapterInfo& info = adapter.info();
    const AdapterLimits& l = info.limits;
    std::printf("[%u] %s%s\n", adapter.index(), info.name.c_str(), isSelected ? "   <- selected" : "");
    std::printf("    type         %.*s\n", int(toString(info.type).size()), toString(info.type).data());
    std::printf("    driver       %s%s%s\n", info.driverName.c_str(), info.driverInfo.empty() ? "" : ", ",
                info.driverInfo.c_str());
    std::printf("    Vulkan API   %s\n", info.apiVersionString().c_str());
    std::printf("    vendor:id    0x%04x:0x%04x\n", info.vendorId, info.deviceId);
    std::printf("    limits\n");
    printRow("maxTextureDimension2D", std::to_string(l.maxTextureDimension2D));
    printRow("maxComputeWorkgroupSize", triple(l.maxComputeWorkgroupSize));
    printRow("maxComputeInvocationsPerWorkgroup", std::to_string(l.maxComputeInvocationsPerWorkgroup));
    printRow("maxComputeWorkgroupCount", triple(l.maxComputeWorkgroupCount));
    printRow("maxComputeSharedMemoryBytes", std::to_string(l.maxComputeSharedMemoryBytes));
    printRow("maxPushConstantBytes", std::to_string(l.maxPushConstantBytes));
    printRow("maxStorageBufferBindingBytes", std::to_string(l.maxStorageBufferBindingBytes));
    printRow("maxUniformBufferBindingBytes", std::to_string(l.maxUniformBufferBindingBytes));
    printRow("maxBoundDescriptorSets", std::to_string(l.maxBoundDescriptorSets));
    printRow("subgroupSize", std::to_string(l.subgroupSize));
    char period[64];
    std::snprintf(period, sizeof period, "yes, %.3f ns per tick", l.timestampPeriodNs);
    printRow("timestamps", l.timestampsSupported ? std::string(period) : std::string("no"));
    printRow("device-local memory", mebibytes(l.deviceLocalBytes));
}

int runInfo(std::span<const std::string_view> args) {
    InstanceDesc instanceDesc;
    AdapterRequest request;
    std::string dumpPath;
    for (size_t i = 0; i < args.size(); ++i) {
        std::string value;
        if (takeOption(args, i, "--adapter", value)) {
            request.nameContains = value;
            request.nameFromEnvironment = false;
        } else if (takeOption(args, i, "--dump-graph", value)) {
            dumpPath = value;
        } else if (args[i] == "--validation") {
            instanceDesc.validation = true;
            instanceDesc.validationFromEnvironment = false;
        } else {
            unknownArgument("info", args[i]);
        }
    }

    Instance instance = Instance::create(instanceDesc);
    std::vector<Adapter> adapters = instance.enumerateAdapters();
    // Ask for the default before printing, so the list can mark it; if the request
    // names no adapter that exists, the list still shows what there is.
    Adapter chosen;
    std::string chooseError;
    try {
        chosen = instance.requestAdapter(request);
    } catch (const Error& error) {
        if (error.kind() != ErrorKind::NoAdapter) {
            throw;
        }
        chooseError = error.what();
    }

    std::printf("hush %s: %zu Vulkan adapter%s (validation %s)\n\n", std::string(core::hushVersion()).c_str(), adapters.size(),
                adapters.size() == 1 ? "" : "s", instance.validationEnabled() ? "on" : "off");
    for (const Adapter& adapter : adapters) {
        printAdapter(adapter, chosen && adapter.index() == chosen.index());
        std::printf("\n");
    }
    if (!chosen) {
        throw Error(ErrorKind::NoAdapter, chooseError);
    }

    const AdapterInfo& info = chosen.info();
    std::printf("self-check on [%u] %s\n", chosen.index(), info.name.c_str());
    std::fflush(stdout);
    Device device = chosen.createDevice({.label = "hush info"});
    SelfCheckResult check = runSelfCheck(device);
    device.waitIdle();

    auto line = [](const std::string& key, const std::string& value) {
        std::printf("    %-28s %s\n", key.c_str(), value.c_str());
    };
    char text[96];
    std::snprintf(text, sizeof text, "max relative error %.3g", check.bufferMaxError);
    line("saxpy, " + std::to_string(check.width * check.height) + " floats", text);
    std::snprintf(text, sizeof text, "max relative error %.3g", check.imageMaxError);
    line("rgba32f image, " + std::to_string(check.width) + "x" + std::to_string(check.height), text);
    std::snprintf(text, sizeof text, "%.3g", check.tolerance);
    line("tolerance", text);
    if (check.gpuMs) {
        std::snprintf(text, sizeof text, "%.4f ms (timestamps)", *check.gpuMs);
        line("GPU time", text);
    } else {
        line("GPU time", "n/a (the adapter has no compute timestamps)");
    }
    bool passed = check.passed();

    std::printf("render-graph self-check\n");
    std::fflush(stdout);
    const GraphSelfCheckResult graphCheck = runGraphSelfCheck(device);
    std::snprintf(text, sizeof text, "max abs error %.3g (tolerance %.3g)", graphCheck.maxError, graphCheck.tolerance);
    line(std::to_string(graphCheck.frames) + " frames with history", text);
    std::string culled;
    for (const auto& name : graphCheck.culled) culled += (culled.empty() ? "" : ", ") + name;
    line("culled", culled.empty() ? "none" : culled);
    line("compiles", std::to_string(graphCheck.compiles));
    if (graphCheck.timed) {
        std::snprintf(text, sizeof text, "%.4f ms (last frame, timestamps)", graphCheck.totalGpuMs);
        line("GPU time", text);
    }
    if (!dumpPath.empty()) {
        core::writeFileAtomically(dumpPath + ".dot", graphCheck.dot);
        core::writeFileAtomically(dumpPath + ".json", graphCheck.json);
        line("graph written to", dumpPath + ".dot, " + dumpPath + ".json");
    }
    passed = passed && graphCheck.passed();
    if (instance.validationEnabled()) {
        size_t messages = instance.validationMessageCount();
        line("validation messages", std::to_string(messages));
        passed = passed && messages == 0;
    }
    std::printf("%s\n", passed ? "PASS" : "FAIL");
    return passed ? kExitOk : kExitFailed;
}

} // namespace

const Command& infoCommand() {
    static const Command command{
        .name = "info",
        .summary = "list Vulkan adapters and their limits; run a compute self-check",
        .usage = kUsage,
        .run = runInfo,
    };
    return command;
}

} // namespace hush::cli
