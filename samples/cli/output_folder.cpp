#include "output_folder.hpp"

#include <unistd.h>

#include <hush/core/atomic_file.hpp>
#include <hush/core/error.hpp>
#include <hush/core/json.hpp>
#include <hush/core/read_file.hpp>
#include <hush/core/run_environment.hpp>

namespace hush::cli {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(ErrorKind kind, const fs::path& folder, const std::string& what) {
    throw Error(kind, "output folder '" + folder.string() + "': " + what);
}

std::set<std::string> readManifest(const fs::path& folder) {
    const auto path = folder / OutputFolder::kManifest;
    const std::string text = core::readFile(path);
    const core::Json json = core::parseJson(text, path.string());
    core::JsonObject root(json, path.string(), "");
    root.allow("command");
    root.allow("version");
    root.allow("complete");
    std::set<std::string> files;
    const auto list = root.require("outputs");
    for (size_t i = 0; i < list.arraySize(); ++i) {
        const std::string file = list[i].string();
        // A manifest names files inside its folder only: never follow one outside.
        const fs::path p = fs::path(file).lexically_normal();
        if (p.is_absolute() || p.empty() || *p.begin() == "..") list[i].fail("not a path inside the folder");
        files.insert(p.string());
    }
    return files;
}

// The first entry of a folder that is not ours (nothing: "").
std::string firstEntry(const fs::path& folder) {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(folder, ec)) return entry.path().filename().string();
    return "";
}

void checkWritable(const fs::path& folder) {
    const fs::path probe = folder / (".hush-write-probe-" + std::to_string(::getpid()));
    try {
        core::writeFileAtomically(probe, "");
    } catch (const Error& e) {
        fail(ErrorKind::Io, folder, std::string("not writable (") + e.what() + ")");
    }
    std::error_code ignored;
    fs::remove(probe, ignored);
}

} // namespace

OutputFolder::OutputFolder(fs::path folder, std::string command, bool overwrite)
    : folder_(std::move(folder)), command_(std::move(command)) {
    std::error_code ec;
    const auto status = fs::status(folder_, ec);
    if (fs::exists(status) && !fs::is_directory(status))
        fail(ErrorKind::InvalidArgument, folder_, "exists and is not a folder; give --out a folder");
    if (!fs::exists(status)) {
        fs::create_directories(folder_, ec);
        if (ec) fail(ErrorKind::Io, folder_, "cannot be created (" + ec.message() + ")");
    } else if (fs::exists(folder_ / kManifest)) {
        previous_ = readManifest(folder_);
    } else if (const auto entry = firstEntry(folder_); !entry.empty() && !overwrite) {
        fail(ErrorKind::InvalidArgument, folder_,
             "holds files that no hush run wrote (e.g. '" + entry +
                 "'); choose an empty or new folder, or pass --overwrite to write into it anyway");
    }
    checkWritable(folder_);
}

fs::path OutputFolder::file(const fs::path& relative) {
    written_.insert(relative.lexically_normal().string());
    const fs::path full = folder_ / relative;
    std::error_code ec;
    fs::create_directories(full.parent_path(), ec);
    if (ec) fail(ErrorKind::Io, folder_, "cannot create '" + full.parent_path().string() + "' (" + ec.message() + ")");
    return full;
}

void OutputFolder::keep(const fs::path& relative) { kept_.insert(relative.lexically_normal().string()); }

namespace {

// Removes `relative` and its folder once empty (a chain's folder, e.g.).
void removeOutput(const fs::path& folder, const std::string& relative) {
    std::error_code ignored;
    const fs::path file = folder / relative;
    fs::remove(file, ignored);
    if (fs::path dir = file.parent_path(); dir != folder && fs::is_empty(dir, ignored)) fs::remove(dir, ignored);
}

} // namespace

void OutputFolder::finish() {
    std::set<std::string> outputs = written_;
    outputs.insert(kept_.begin(), kept_.end());
    for (const auto& old : previous_)
        if (!outputs.count(old)) removeOutput(folder_, old);
    writeManifest(outputs, true);
    finished_ = true;
}

void OutputFolder::checkpoint() {
    kept_.insert(written_.begin(), written_.end());
    std::set<std::string> outputs = kept_;
    outputs.insert(previous_.begin(), previous_.end());
    writeManifest(outputs, false);
}

OutputFolder::~OutputFolder() {
    if (!finished_) abandon();
}

void OutputFolder::abandon() noexcept {
    if (written_.empty()) return;   // failed before writing: the folder is as it was
    try {
        std::set<std::string> left = kept_;
        for (const auto& file : written_)
            if (!kept_.count(file)) removeOutput(folder_, file);
        std::error_code ignored;
        for (const auto& old : previous_)
            if (!written_.count(old) && fs::exists(folder_ / old, ignored)) left.insert(old);
        writeManifest(left, false);
    } catch (...) {
        // Already failing: the first error is the one the user sees.
    }
}

void OutputFolder::writeManifest(const std::set<std::string>& outputs, bool complete) const {
    core::Json manifest = {{"command", command_}, {"version", std::string(core::hushVersion())},
                           {"complete", complete}, {"outputs", core::Json::array()}};
    for (const auto& f : outputs) manifest["outputs"].push_back(f);
    core::writeFileAtomically(folder_ / kManifest, manifest.dump(1) + "\n");
}

} // namespace hush::cli
