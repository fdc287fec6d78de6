#pragma once
// A network's weights in the safetensors layout (Hugging Face's format, as PyTorch
// tools write it; the training toolkit writes it by hand, samples/rdae_training):
//   8 bytes   N, the header's length, little-endian uint64
//   N bytes   JSON: {"<tensor>": {"dtype": "F16" | "F32", "shape": [...],
//                                 "data_offsets": [begin, end]}, ...,
//                    "__metadata__": {"<key>": "<string>", ...}}
//   the rest  the tensors' bytes, little-endian, row-major; offsets count from here
// Everything is checked on reading; an error names the file and the tensor.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace hush::passes {

class RdaeWeights {
public:
    // Throws hush::Error naming the file: missing, truncated, a header that is not
    // JSON or not this layout, offsets outside the data or overlapping.
    static RdaeWeights read(const std::filesystem::path& file);
    static RdaeWeights parse(std::span<const std::byte> bytes, const std::string& source);

    // Tensor `name` as floats, which must have `shape`. Throws hush::Error naming the
    // source and the tensor when it is missing, has another shape, or holds a
    // non-finite value.
    std::vector<float> tensor(const std::string& name, const std::vector<uint64_t>& shape) const;
    bool has(const std::string& name) const { return tensors_.count(name) != 0; }
    // Tensor `name`'s shape; throws hush::Error (NotFound) naming it when missing.
    const std::vector<uint64_t>& shape(const std::string& name) const;
    std::vector<std::string> names() const;
    std::optional<std::string> metadata(const std::string& key) const;
    const std::string& source() const { return source_; }

private:
    struct Entry {
        bool half = false;
        std::vector<uint64_t> shape;
        uint64_t begin = 0;
        uint64_t end = 0;
    };
    std::string source_;
    std::map<std::string, Entry> tensors_;
    std::map<std::string, std::string> metadata_;
    std::vector<std::byte> data_;
};

} // namespace hush::passes
