#pragma once
// Reading a whole file, with the errors every reader of a user's file wants: a
// missing file, a folder given for a file, and a failed read each name the file.
#include <filesystem>
#include <string>

namespace hush::core {

// The file's bytes. Throws hush::Error: NotFound ("[<what> ]<path>: no such file" or
// "cannot be opened"), InvalidArgument when it is not a regular file, Io on a read
// error. `what` says what the file is for ("chain file", "weights file").
std::string readFile(const std::filesystem::path& path, const std::string& what = "");

} // namespace hush::core
