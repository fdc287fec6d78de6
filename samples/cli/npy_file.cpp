#include "npy_file.hpp"

#include <cstring>
#include <string>

#include <hush/core/atomic_file.hpp>
#include <hush/core/error.hpp>
#include <hush/core/half.hpp>

namespace hush::cli {

void writeNpyHalf(const std::filesystem::path& file, const std::vector<uint64_t>& shape, const std::vector<float>& values) {
    uint64_t count = 1;
    std::string dims;
    for (auto d : shape) {
        count *= d;
        dims += std::to_string(d) + ",";
    }
    if (count != values.size())
        throw Error(ErrorKind::InvalidArgument, file.string() + ": " + std::to_string(values.size()) +
                                                    " values do not fill the shape (" + dims + ")");
    if (shape.size() > 1) dims.pop_back();   // (4,) for one dimension, (2,3) for more
    std::string header = "{'descr': '<f2', 'fortran_order': False, 'shape': (" + dims + "), }";
    const size_t preamble = 10;   // magic (6), version (2), header length (2)
    header.append((64 - (preamble + header.size() + 1) % 64) % 64, ' ');
    header += '\n';
    std::string bytes = "\x93NUMPY";
    bytes += char(1);
    bytes += char(0);
    bytes += char(header.size() & 0xFF);
    bytes += char(header.size() >> 8);
    bytes += header;
    const size_t start = bytes.size();
    bytes.resize(start + 2 * values.size());
    for (size_t i = 0; i < values.size(); ++i) {
        const uint16_t h = core::floatToHalf(values[i]);
        std::memcpy(bytes.data() + start + 2 * i, &h, 2);   // little-endian host (x86-64, arm64)
    }
    core::writeFileAtomically(file, bytes);
}

} // namespace hush::cli
