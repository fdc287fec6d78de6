#pragma once
// A `hush` subcommand. Each lives in its own command_<name>.cpp and is listed in
// main.cpp's table; adding one (render, denoise) touches nothing else.
#include <span>
#include <string>
#include <string_view>

#include <hush/core/arguments.hpp>
#include <hush/core/atomic_file.hpp>

namespace hush::cli {

// Every subcommand parses its options with core's helpers.
using core::parseCount;
using core::parseSize;
using core::splitList;
using core::takeOption;

// Exit codes shared by every subcommand (documented in `hush --help`).
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailed = 1;   // ran, and the result was wrong (e.g. self-check)
inline constexpr int kExitError = 2;    // could not run: bad arguments, no device, ...

struct Command {
    std::string_view name;
    std::string_view summary;   // one line, for `hush --help`
    std::string_view usage;     // the full text of `hush <name> --help`
    // Runs with the arguments after the subcommand's name (--help already handled).
    // Returns the exit code; throws hush::Error when it cannot run.
    int (*run)(std::span<const std::string_view> args);
};

const Command& infoCommand();
const Command& renderCommand();
const Command& denoiseCommand();
const Command& demoCommand();
const Command& datasetCommand();
const Command& sweepCommand();
const Command& checkCommand();

// hush::Error (InvalidArgument) for an argument a subcommand does not know.
[[noreturn]] void unknownArgument(std::string_view command, std::string_view arg);

} // namespace hush::cli
