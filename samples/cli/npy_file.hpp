#pragma once
// NumPy's .npy format (version 1.0), written for the training toolkit to read with
// numpy.load: the magic "\x93NUMPY", the version, a little-endian uint16 header length,
// a Python dict literal {'descr': '<f2', 'fortran_order': False, 'shape': (...), }
// padded with spaces and a newline to a multiple of 64 bytes, then the data, C order.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace hush::cli {

// Writes `values` as float16 ("<f2") of `shape`, atomically (core::writeFileAtomically).
void writeNpyHalf(const std::filesystem::path& file, const std::vector<uint64_t>& shape, const std::vector<float>& values);

} // namespace hush::cli
