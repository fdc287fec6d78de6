#include <cstdio>
#include <filesystem>
#include <fstream>

#include <hush/rhi/error.hpp>

#include "command.hpp"

namespace hush::cli {

void writeTextFile(const std::string& path, const std::string& text) {
    const std::filesystem::path target(path);
    if (target.has_parent_path() && !std::filesystem::is_directory(target.parent_path()))
        throw Error(ErrorKind::NotFound, "cannot write '" + path + "': the folder '" + target.parent_path().string() +
                                             "' does not exist");
    const std::string temporary = path + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out << text;
        out.flush();
        if (!out) {
            std::remove(temporary.c_str());
            throw Error(ErrorKind::InvalidArgument, "cannot write '" + temporary + "'");
        }
    }
    std::error_code error;
    std::filesystem::rename(temporary, target, error);
    if (error) {
        std::remove(temporary.c_str());
        throw Error(ErrorKind::InvalidArgument, "cannot write '" + path + "': " + error.message());
    }
}

} // namespace hush::cli
