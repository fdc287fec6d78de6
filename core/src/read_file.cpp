#include <hush/core/read_file.hpp>

#include <fstream>
#include <sstream>

#include <hush/core/error.hpp>

namespace hush::core {

std::string readFile(const std::filesystem::path& path, const std::string& what) {
    const std::string prefix = (what.empty() ? "" : what + " ") + path.string() + ": ";
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (!std::filesystem::exists(status)) throw Error(ErrorKind::NotFound, prefix + "no such file");
    // ifstream happily "opens" a folder and then reads nothing: say what is wrong instead.
    if (!std::filesystem::is_regular_file(status))
        throw Error(ErrorKind::InvalidArgument, prefix + "not a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(ErrorKind::NotFound, prefix + "cannot be opened");
    std::ostringstream bytes;
    bytes << in.rdbuf();
    if (in.bad()) throw Error(ErrorKind::Io, prefix + "read error");
    return std::move(bytes).str();
}

} // namespace hush::core
