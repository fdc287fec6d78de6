#pragma once
// A per-process scratch folder for harnesses whose reader takes a path, not bytes
// (the EXR readers go through OpenEXR's file streams): the input is written to a
// file there on every run. It lives under /dev/shm when that exists, so the
// fuzzer's speed is not the disk's.
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace hush::fuzz {

// Created on first use, removed when the process exits normally.
struct ScratchFolder {
    std::filesystem::path path;
    ScratchFolder() {
        const std::filesystem::path base =
            std::filesystem::exists("/dev/shm") ? "/dev/shm" : std::filesystem::temp_directory_path();
        path = base / ("hush-fuzz-" + std::to_string(getpid()));
        std::filesystem::create_directories(path);
    }
    ~ScratchFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
};

inline const std::filesystem::path& scratchFolder() {
    static const ScratchFolder folder;
    return folder.path;
}

inline std::string writeScratch(const std::string& name, const std::uint8_t* data, std::size_t size) {
    const auto path = scratchFolder() / name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    return path.string();
}

} // namespace hush::fuzz
