#pragma once
// 8-bit RGB PNG files (libpng), written atomically like every hush output: the
// bytes go to a temporary beside the target, renamed over it only when complete.
#include <cstdint>
#include <span>
#include <string>

namespace hush::cli {

// `rgb` holds width * height * 3 bytes, rows from the top. Throws hush::Error naming
// the path on any failure; an existing file at `path` is then left untouched.
void writePng(const std::string& path, uint32_t width, uint32_t height, std::span<const uint8_t> rgb);

} // namespace hush::cli
