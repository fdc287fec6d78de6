#include <hush/core/atomic_file.hpp>

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include <hush/core/error.hpp>

namespace hush::core {

namespace fs = std::filesystem;

void writeAtomically(const fs::path& target, const std::function<void(const std::string& temporary)>& write) {
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::error_code ignored;
    if (!fs::is_directory(folder, ignored))
        throw Error(ErrorKind::NotFound,
                    "cannot write '" + target.string() + "': the folder '" + folder.string() + "' does not exist");
    const std::string temporary = target.string() + ".tmp-" + std::to_string(::getpid());
    std::string failure;
    try {
        write(temporary);
        std::error_code error;
        fs::rename(temporary, target, error);
        if (!error) return;
        failure = error.message();
    } catch (const std::exception& e) {
        failure = e.what();
    }
    fs::remove(temporary, ignored);
    throw Error(ErrorKind::Io, "cannot write '" + target.string() + "': " + failure);
}

void writeFileAtomically(const fs::path& target, std::string_view bytes) {
    writeAtomically(target, [&](const std::string& temporary) {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) throw std::runtime_error(std::string("cannot create it: ") + std::strerror(errno));
        out.write(bytes.data(), std::streamsize(bytes.size()));
        out.close();
        // Only a closed stream tells that the last block reached the disk.
        if (!out) throw std::runtime_error(std::string("writing failed (disk full?): ") + std::strerror(errno));
    });
}

} // namespace hush::core
