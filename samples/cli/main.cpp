// `hush`: the command line. Finds the subcommand, prints help, and turns errors
// into messages and exit codes instead of crashes.
#include <array>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <new>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <hush/core/atomic_file.hpp>
#include <hush/core/error.hpp>
#include <hush/core/run_environment.hpp>
#include <hush/rhi/fault_injection.hpp>

#include "command.hpp"

namespace hush::cli {
namespace {

// Every subcommand, in the order `hush --help` lists them.
std::array<const Command*, 7> commands() {
    return {&demoCommand(),    &denoiseCommand(), &sweepCommand(), &checkCommand(),
            &renderCommand(), &datasetCommand(), &infoCommand()};
}

std::string commandNames() {
    std::string names;
    for (const Command* command : commands()) {
        names += names.empty() ? "" : ", ";
        names += command->name;
    }
    return names;
}

void printUsage(std::FILE* out) {
    std::fprintf(out,
                 "hush %s: real-time denoising of path-traced images, on Vulkan.\n"
                 "\n"
                 "usage: hush <command> [options]\n"
                 "       hush <command> --help\n"
                 "\n"
                 "commands:\n",
                 std::string(core::hushVersion()).c_str());
    for (const Command* command : commands()) {
        std::fprintf(out, "  %-10.*s %.*s\n", int(command->name.size()), command->name.data(),
                     int(command->summary.size()), command->summary.data());
    }
    std::fprintf(out,
                 "\n"
                 "environment:\n"
                 "  HUSH_ADAPTER=<text>       use the first adapter whose name contains <text>\n"
                 "  HUSH_VALIDATION=1         enable the Vulkan validation layer (with sync validation)\n"
                 "  HUSH_VULKAN_LOADER=<path> open this Vulkan loader instead of libvulkan.so.1\n"
                 "  HUSH_INJECT_FAULT=<fault>[:<n>]  for tests: the (n+1)-th device allocation or\n"
                 "                            submission fails (out-of-device-memory, device-lost)\n"
                 "\n"
                 "exit status: 0 success, 1 a check failed, 2 could not run (the message says why)\n");
}

// HUSH_INJECT_FAULT: how tests/cli/faults.sh makes the driver fail on demand.
void injectFaultFromEnvironment() {
    const char* text = std::getenv("HUSH_INJECT_FAULT");
    if (!text || !*text) return;
    const std::string_view spec(text);
    const auto colon = spec.find(':');
    uint32_t skip = 0;
    if (colon != std::string_view::npos) {
        const std::string count(spec.substr(colon + 1));
        char* end = nullptr;
        const unsigned long value = std::strtoul(count.c_str(), &end, 10);
        if (count.empty() || *end != '\0' || value > 1000000)
            throw Error(ErrorKind::InvalidArgument, "HUSH_INJECT_FAULT: '" + count + "' is not a count (0 to 1000000)");
        skip = uint32_t(value);
    }
    rhi::injectFault(rhi::parseInjectedFault(spec.substr(0, colon)), skip);
}

bool isHelp(std::string_view arg) {
    return arg == "--help" || arg == "-h" || arg == "help";
}

int dispatch(std::span<const std::string_view> args) {
    if (args.empty()) {
        printUsage(stderr);
        return kExitError;
    }
    if (isHelp(args[0])) {
        printUsage(stdout);
        return kExitOk;
    }
    injectFaultFromEnvironment();
    if (args[0] == "--version") {
        std::printf("hush %s\n", std::string(core::hushVersion()).c_str());
        return kExitOk;
    }
    for (const Command* command : commands()) {
        if (command->name != args[0]) {
            continue;
        }
        auto rest = args.subspan(1);
        for (std::string_view arg : rest) {
            if (arg == "--help" || arg == "-h") {
                std::printf("%.*s", int(command->usage.size()), command->usage.data());
                return kExitOk;
            }
        }
        return command->run(rest);
    }
    throw Error(ErrorKind::InvalidArgument,
                "unknown command '" + std::string(args[0]) + "'; available commands: " +
                    commandNames() + " (see hush --help)");
}

} // namespace

void unknownArgument(std::string_view command, std::string_view arg) {
    throw Error(ErrorKind::InvalidArgument, "unknown argument '" + std::string(arg) + "' for hush " +
                                                std::string(command) + " (see hush " +
                                                std::string(command) + " --help)");
}

} // namespace hush::cli

int main(int argc, char** argv) {
    hush::core::removeTemporariesOnSignal();   // Ctrl-C leaves no half-written file behind
    std::vector<std::string_view> args(argv + 1, argv + argc);
    try {
        return hush::cli::dispatch(args);
    } catch (const hush::Error& error) {
        std::fflush(stdout);
        std::fprintf(stderr, "hush: error (%s): %s\n", hush::toString(error.kind()), error.what());
        return hush::cli::kExitError;
    } catch (const std::filesystem::filesystem_error& error) {
        // The file system refused (a folder given as a file, permissions, a full disk):
        // the user's to fix, with the path it names.
        std::fflush(stdout);
        std::fprintf(stderr, "hush: error (io): '%s': %s\n", error.path1().string().c_str(),
                     error.code().message().c_str());
        return hush::cli::kExitError;
    } catch (const std::bad_alloc&) {
        std::fflush(stdout);
        std::fprintf(stderr, "hush: error (out-of-memory): the host ran out of memory; try a smaller --size or "
                             "fewer frames\n");
        return hush::cli::kExitError;
    } catch (const std::exception& error) {
        // Not a hush::Error: a bug in hush rather than in the input; say so.
        std::fflush(stdout);
        std::fprintf(stderr, "hush: internal error: %s\n", error.what());
        return hush::cli::kExitError;
    }
}
