#include <algorithm>
#include <cmath>

#include <hush/graph/graph_model.hpp>

namespace hush::graph {

rhi::Extent2D SizeSpec::resolve(rhi::Extent2D output) const {
    if (mode == Mode::Absolute) return extent;
    const uint32_t pad = std::max<uint32_t>(1, padTo);
    auto scaled = [&](uint32_t v) {
        const uint64_t padded = (uint64_t(v) + pad - 1) / pad * pad;
        return std::max<uint32_t>(1, uint32_t(std::lround(double(padded) * scale)));
    };
    return {scaled(output.width) * std::max<uint32_t>(1, tilesX), scaled(output.height) * std::max<uint32_t>(1, tilesY)};
}

bool isWrite(Access access) {
    return access == Access::StorageWrite || access == Access::StorageReadWrite || access == Access::CopyDst;
}

bool isRead(Access access) { return access != Access::StorageWrite && access != Access::CopyDst; }

rhi::ResourceState toState(Access access) {
    using S = rhi::ResourceState;
    switch (access) {
    case Access::SampledRead: return S::SampledRead;
    case Access::StorageRead: return S::StorageRead;
    case Access::StorageWrite: return S::StorageWrite;
    case Access::StorageReadWrite: return S::StorageReadWrite;
    case Access::UniformRead: return S::UniformRead;
    case Access::IndirectRead: return S::IndirectRead;
    case Access::CopySrc: return S::CopySrc;
    case Access::CopyDst: return S::CopyDst;
    }
    return S::General;
}

const char* toString(Access access) {
    switch (access) {
    case Access::SampledRead: return "sampled-read";
    case Access::StorageRead: return "storage-read";
    case Access::StorageWrite: return "storage-write";
    case Access::StorageReadWrite: return "storage-read-write";
    case Access::UniformRead: return "uniform-read";
    case Access::IndirectRead: return "indirect-read";
    case Access::CopySrc: return "copy-src";
    case Access::CopyDst: return "copy-dst";
    }
    return "unknown";
}

uint32_t GraphModel::historySource(uint32_t historyResource) const {
    if (historyResource >= resources.size()) return kNone;
    const auto& h = resources[historyResource];
    return h.origin == ResourceOrigin::History ? h.historySource : kNone;
}

} // namespace hush::graph
