#include "objects.hpp"
#include "vk_check.hpp"

namespace hush::rhi {
namespace detail {

QuerySetImpl::~QuerySetImpl() {
    if (pool != VK_NULL_HANDLE) device->vk.vkDestroyQueryPool(device->device, pool, nullptr);
}

} // namespace detail

using namespace detail;

QuerySet Device::createQuerySet(const QuerySetDesc& desc) const {
    auto* device = checked(impl_, "Device");
    if (desc.count == 0) fail(ErrorKind::InvalidArgument, "query set '" + desc.label + "' has count 0");
    if (!device->info.limits.timestampsSupported)
        fail(ErrorKind::Unsupported, "query set '" + desc.label + "': adapter '" + device->info.name +
                                         "' has no timestamps on its compute queue");
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = desc.count;
    auto impl = std::make_shared<QuerySetImpl>();
    impl->device = impl_;
    impl->count = desc.count;
    impl->label = desc.label;
    checkVk(device->vk.vkCreateQueryPool(device->device, &info, nullptr, &impl->pool),
            "vkCreateQueryPool for query set '" + desc.label + "'");
    return QuerySet(std::move(impl));
}

const std::string& QuerySet::label() const { return checked(impl_, "QuerySet")->label; }
uint32_t QuerySet::count() const { return checked(impl_, "QuerySet")->count; }

std::vector<uint64_t> QuerySet::readTicks(uint32_t first, uint32_t count) const {
    auto* impl = checked(impl_, "QuerySet");
    if (count == 0 || first + count > impl->count)
        fail(ErrorKind::InvalidArgument, "reading queries [" + std::to_string(first) + ", " +
                                             std::to_string(first + count) + ") of query set '" + impl->label +
                                             "', which has " + std::to_string(impl->count));
    // Each result is a (value, availability) pair; never wait, so an unwritten query
    // is an error instead of a hang.
    std::vector<uint64_t> raw(size_t(count) * 2);
    const VkResult result = impl->device->vk.vkGetQueryPoolResults(
        impl->device->device, impl->pool, first, count, raw.size() * sizeof(uint64_t), raw.data(), 2 * sizeof(uint64_t),
        VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WITH_AVAILABILITY_BIT);
    if (result != VK_NOT_READY) checkVk(result, "vkGetQueryPoolResults for query set '" + impl->label + "'");
    std::vector<uint64_t> ticks(count);
    for (uint32_t i = 0; i < count; ++i) {
        if (raw[2 * i + 1] == 0)
            fail(ErrorKind::InvalidArgument, "timestamp " + std::to_string(first + i) + " of query set '" + impl->label +
                                                 "' is not available: it was never written, or the submission that "
                                                 "writes it has not completed (wait for it first)");
        ticks[i] = raw[2 * i];
    }
    return ticks;
}

void QuerySet::readTicks(uint32_t first, std::span<uint64_t> out) const {
    auto* impl = checked(impl_, "QuerySet");
    if (out.empty() || first + out.size() > impl->count)
        fail(ErrorKind::InvalidArgument, "reading " + std::to_string(out.size()) + " queries from " +
                                             std::to_string(first) + " of query set '" + impl->label + "', which has " +
                                             std::to_string(impl->count));
    // Without the availability bit Vulkan answers VK_NOT_READY when any is missing.
    const VkResult result = impl->device->vk.vkGetQueryPoolResults(
        impl->device->device, impl->pool, first, uint32_t(out.size()), out.size_bytes(), out.data(), sizeof(uint64_t),
        VK_QUERY_RESULT_64_BIT);
    if (result == VK_NOT_READY)
        fail(ErrorKind::InvalidArgument, "timestamps of query set '" + impl->label +
                                             "' are not available: wait for the submission that writes them");
    if (result < 0) checkVk(result, "vkGetQueryPoolResults for query set '" + impl->label + "'");
}

double QuerySet::elapsedMs(uint32_t beginIndex, uint32_t endIndex) const {
    auto* impl = checked(impl_, "QuerySet");
    const auto begin = readTicks(beginIndex, 1)[0];
    const auto end = readTicks(endIndex, 1)[0];
    const double period = impl->device->info.limits.timestampPeriodNs;
    // Ticks are unsigned and may wrap past timestampValidBits; a begin after its end
    // means the pair was not written in order, which is the caller's mistake.
    if (end < begin)
        fail(ErrorKind::InvalidArgument, "query set '" + impl->label + "': timestamp " + std::to_string(endIndex) +
                                             " is earlier than " + std::to_string(beginIndex));
    return double(end - begin) * period * 1e-6;
}

} // namespace hush::rhi
