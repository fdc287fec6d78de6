#pragma once
// The folder a command writes (--out), guarded so that no run costs a user data:
//  - it must be empty, missing, or hold a manifest (hush-run.json) that an earlier
//    hush run wrote; anything else is refused unless --overwrite;
//  - it must be writable, found out before any work;
//  - every file the run writes is recorded; at the end the files the previous run's
//    manifest lists and this run did not write again (stale outputs of a longer
//    earlier run) are removed, and the new manifest is written;
//  - a run that fails (finish() never called) leaves no partial output: the files it
//    wrote are removed when the folder object is destroyed, and the manifest then
//    lists what is left of earlier runs, so that a rerun needs no --overwrite.
#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace hush::cli {

class OutputFolder {
public:
    static constexpr const char* kManifest = "hush-run.json";

    // Throws hush::Error naming the folder and what to do: a file given for a folder,
    // a folder that cannot be created or written, or files of unknown origin (without
    // `overwrite`).
    OutputFolder(std::filesystem::path folder, std::string command, bool overwrite);
    OutputFolder(const OutputFolder&) = delete;
    OutputFolder& operator=(const OutputFolder&) = delete;
    ~OutputFolder();

    const std::filesystem::path& path() const { return folder_; }
    // The full path of `relative`, recorded as one of this run's outputs; its folder
    // is created.
    std::filesystem::path file(const std::filesystem::path& relative);
    // Records `relative` (e.g. input frames reused from an earlier run) without writing it.
    void keep(const std::filesystem::path& relative);
    // Every file written so far survives a failure or an interruption of the rest of
    // the run (the finished steps of a resumable job: hush sweep's frames and
    // results), and the manifest (complete: false) says so, so that the same command
    // resumes there without --overwrite.
    void checkpoint();
    // Removes the earlier run's stale outputs and writes the manifest.
    void finish();

private:
    void abandon() noexcept;
    void writeManifest(const std::set<std::string>& outputs, bool complete) const;

    std::filesystem::path folder_;
    std::string command_;
    std::set<std::string> previous_, written_, kept_;
    bool finished_ = false;
};

} // namespace hush::cli
