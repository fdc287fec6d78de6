#pragma once
// Writing a file so that a reader, or a user after a crash, sees either the old file
// or the whole new one, never half of it: the bytes go to a temporary file beside the
// target ("<target>.tmp-<pid>", so two processes never share one), which is renamed
// over the target (atomic within one file system) only once it is complete.
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace hush::core {

// `write` writes the whole file at the path it is given (for libraries that open the
// file themselves: OpenEXR, libpng). If it throws, or the rename fails, the temporary
// is removed and hush::Error names the target: NotFound when its folder does not
// exist, Io otherwise (with the reason `write` or the file system gave).
void writeAtomically(const std::filesystem::path& target, const std::function<void(const std::string& temporary)>& write);

// Writes `bytes` through writeAtomically.
void writeFileAtomically(const std::filesystem::path& target, std::string_view bytes);

// Makes SIGINT and SIGTERM remove the temporaries of writes in flight before the
// process dies of the signal as it would have: a stopped run leaves no
// "<target>.tmp-<pid>" behind. Call once, early in main().
void removeTemporariesOnSignal();

} // namespace hush::core
