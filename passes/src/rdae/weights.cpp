#include <hush/passes/rdae/weights.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

#include <hush/core/error.hpp>
#include <hush/core/half.hpp>
#include <hush/core/json.hpp>
#include <hush/core/read_file.hpp>

namespace hush::passes {

namespace {

std::string shapeText(const std::vector<uint64_t>& shape) {
    std::string s = "[";
    for (size_t i = 0; i < shape.size(); ++i) s += (i ? ", " : "") + std::to_string(shape[i]);
    return s + "]";
}

uint64_t elementCount(const std::vector<uint64_t>& shape) {
    uint64_t n = 1;
    for (auto d : shape) n *= d;
    return n;
}

} // namespace

RdaeWeights RdaeWeights::read(const std::filesystem::path& file) {
    const std::string bytes = core::readFile(file, "weights file");
    return parse(std::as_bytes(std::span(bytes.data(), bytes.size())), file.string());
}

RdaeWeights RdaeWeights::parse(std::span<const std::byte> bytes, const std::string& source) {
    auto fail = [&](const std::string& what) -> void { throw Error(ErrorKind::InvalidArgument, source + ": " + what); };
    if (bytes.size() < 8) fail("truncated: " + std::to_string(bytes.size()) + " bytes, not even the header's length");
    uint64_t headerBytes = 0;
    for (int i = 7; i >= 0; --i) headerBytes = headerBytes << 8 | uint64_t(bytes[size_t(i)]);
    if (headerBytes > bytes.size() - 8)
        fail("truncated: the header says it is " + std::to_string(headerBytes) + " bytes, the file has " +
             std::to_string(bytes.size() - 8) + " after the length");
    const std::string_view headerText(reinterpret_cast<const char*>(bytes.data()) + 8, size_t(headerBytes));
    const core::Json header = core::parseJson(headerText, source + " (header)");
    core::JsonObject root(header, source, "");

    RdaeWeights w;
    w.source_ = source;
    const auto data = bytes.subspan(8 + size_t(headerBytes));
    w.data_.assign(data.begin(), data.end());
    for (const auto& [name, value] : header.items()) {
        if (name == "__metadata__") {
            for (const auto& [key, text] : value.items())
                w.metadata_[key] = core::JsonValue(text, source, "__metadata__." + key).string();
            root.allow(name);
            continue;
        }
        core::JsonObject tensor(root.require(name));
        Entry e;
        const std::string dtype = tensor.require("dtype").string();
        if (dtype != "F16" && dtype != "F32") tensor.fail("tensor '" + name + "': dtype " + dtype + ", expected F16 or F32");
        e.half = dtype == "F16";
        const auto shape = tensor.require("shape");
        for (size_t i = 0; i < shape.arraySize(0, 8); ++i) e.shape.push_back(shape[i].index());
        const auto offsets = tensor.require("data_offsets");
        offsets.arraySize(2, 2);
        e.begin = offsets[0].index();
        e.end = offsets[1].index();
        const uint64_t expected = elementCount(e.shape) * (e.half ? 2 : 4);
        if (e.end < e.begin || e.end - e.begin != expected)
            tensor.fail("tensor '" + name + "': data_offsets [" + std::to_string(e.begin) + ", " +
                        std::to_string(e.end) + "] do not hold " + shapeText(e.shape) + " of " + dtype);
        if (e.end > w.data_.size())
            fail("truncated: tensor '" + name + "' ends at byte " + std::to_string(e.end) + " of the data, which has " +
                 std::to_string(w.data_.size()));
        tensor.finish();
        w.tensors_[name] = e;
    }
    root.finish();
    return w;
}

const std::vector<uint64_t>& RdaeWeights::shape(const std::string& name) const {
    const auto it = tensors_.find(name);
    if (it == tensors_.end())
        throw Error(ErrorKind::NotFound, source_ + ": no tensor '" + name + "' (the file has " +
                                             std::to_string(tensors_.size()) + "; is it a weights file of this network?)");
    return it->second.shape;
}

std::vector<float> RdaeWeights::tensor(const std::string& name, const std::vector<uint64_t>& shape) const {
    this->shape(name);   // the missing-tensor error
    const Entry& e = tensors_.at(name);
    if (e.shape != shape)
        throw Error(ErrorKind::InvalidArgument, source_ + ": tensor '" + name + "' has shape " + shapeText(e.shape) +
                                                    ", the network needs " + shapeText(shape));
    std::vector<float> values(elementCount(shape));
    const std::byte* p = data_.data() + e.begin;
    for (size_t i = 0; i < values.size(); ++i) {
        if (e.half) {
            uint16_t bits;
            std::memcpy(&bits, p + 2 * i, 2);
            values[i] = core::halfToFloat(bits);
        } else {
            std::memcpy(&values[i], p + 4 * i, 4);
        }
        if (!std::isfinite(values[i]))
            throw Error(ErrorKind::InvalidArgument, source_ + ": tensor '" + name + "' holds a non-finite value (" +
                                                        std::to_string(values[i]) + ") at element " + std::to_string(i));
    }
    return values;
}

std::vector<std::string> RdaeWeights::names() const {
    std::vector<std::string> out;
    for (const auto& [name, entry] : tensors_) out.push_back(name);
    return out;
}

std::optional<std::string> RdaeWeights::metadata(const std::string& key) const {
    const auto it = metadata_.find(key);
    if (it == metadata_.end()) return std::nullopt;
    return it->second;
}

} // namespace hush::passes
