#include "specialization.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include <hush/core/error.hpp>

namespace hush::rhi::detail {
namespace {

std::string constantNames(const ShaderReflection& reflection) {
    if (reflection.constants.empty()) return "none";
    std::string names;
    for (const auto& c : reflection.constants) names += (names.empty() ? "'" : ", '") + c.name + "'";
    return names;
}

// The 32 bits Vulkan reads for `value` in a constant of `type`.
uint32_t bitsOf(const std::string& where, const ShaderConstant& constant, double value) {
    auto fail = [&](const std::string& why) {
        throw Error(ErrorKind::InvalidArgument, where + ": " + std::to_string(value) + " " + why);
    };
    switch (constant.type) {
    case ScalarType::Float32:
        if (!std::isfinite(value) || std::fabs(value) > double(std::numeric_limits<float>::max()))
            fail("is not a finite float");
        return std::bit_cast<uint32_t>(float(value));
    case ScalarType::Int32:
        if (value != std::trunc(value) || value < double(std::numeric_limits<int32_t>::min()) ||
            value > double(std::numeric_limits<int32_t>::max()))
            fail("is not a whole number in the int range");
        return std::bit_cast<uint32_t>(int32_t(value));
    case ScalarType::Uint32:
        if (value != std::trunc(value) || value < 0.0 || value > double(std::numeric_limits<uint32_t>::max()))
            fail("is not a whole number in the uint range");
        return uint32_t(value);
    }
    return 0;
}

} // namespace

Specialization specialize(const std::string& pipeline, const ShaderReflection& reflection,
                          const std::vector<ConstantEntry>& constants) {
    Specialization s;
    for (size_t i = 0; i < constants.size(); ++i) {
        const ConstantEntry& entry = constants[i];
        const std::string where = "pipeline '" + pipeline + "': constant '" + entry.key + "'";
        const auto it = std::find_if(reflection.constants.begin(), reflection.constants.end(),
                                     [&](const ShaderConstant& c) { return c.name == entry.key; });
        if (it == reflection.constants.end())
            throw Error(ErrorKind::InvalidArgument,
                        where + ": the shader has no such specialization constant (it has " + constantNames(reflection) + ")");
        for (size_t j = 0; j < i; ++j)
            if (constants[j].key == entry.key) throw Error(ErrorKind::InvalidArgument, where + " is given twice");
        s.entries.push_back({it->id, uint32_t(s.data.size() * sizeof(uint32_t)), sizeof(uint32_t)});
        s.data.push_back(bitsOf(where, *it, entry.value));
    }
    s.info.mapEntryCount = uint32_t(s.entries.size());
    s.info.pMapEntries = s.entries.data();
    s.info.dataSize = s.data.size() * sizeof(uint32_t);
    s.info.pData = s.data.data();
    return s;
}

} // namespace hush::rhi::detail
