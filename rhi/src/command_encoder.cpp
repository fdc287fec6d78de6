// CommandEncoder and ComputePassEncoder: record into one VkCommandBuffer, checking
// the things that would otherwise be undefined behaviour (unbound sets, calls out of
// order) and keeping every object used alive until the submission completes.
#include <algorithm>

#include <hush/rhi/push_constants.hpp>

#include "objects.hpp"
#include "vk_check.hpp"
#include "vk_convert.hpp"

namespace hush::rhi {
namespace detail {

CommandEncoderImpl::~CommandEncoderImpl() {
    if (!external && pool != VK_NULL_HANDLE) device->vk.vkDestroyCommandPool(device->device, pool, nullptr);
}

CommandBufferImpl::~CommandBufferImpl() {
    if (!external && pool != VK_NULL_HANDLE) device->vk.vkDestroyCommandPool(device->device, pool, nullptr);
}

namespace {

void beginRecording(DeviceImpl& device, VkCommandBuffer cmd, bool reusable) {
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = reusable ? 0 : VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    checkVk(device.vk.vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
}

} // namespace

void CommandEncoderImpl::requireRecording(const char* call) const {
    if (finished)
        fail(ErrorKind::InvalidArgument, std::string(call) + " on command encoder '" + label + "' after finish()");
}

void CommandEncoderImpl::requireOutsidePass(const char* call) const {
    requireRecording(call);
    if (inPass)
        fail(ErrorKind::InvalidArgument, std::string(call) + " on command encoder '" + label +
                                             "' while compute pass '" + passLabel + "' is open; call end() first");
}

std::shared_ptr<CommandEncoderImpl> makeEncoder(const std::shared_ptr<DeviceImpl>& device, const std::string& label,
                                                VkCommandBuffer external, bool reusable, bool trackLifetimes) {
    auto impl = std::make_shared<CommandEncoderImpl>();
    impl->device = device;
    impl->label = label;
    impl->reusable = reusable && external == VK_NULL_HANDLE;
    impl->trackLifetimes = trackLifetimes;
    if (external != VK_NULL_HANDLE) {
        impl->external = true;
        impl->commandBuffer = external;
        return impl;
    }
    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    poolInfo.queueFamilyIndex = device->queueFamily;
    checkVk(device->vk.vkCreateCommandPool(device->device, &poolInfo, nullptr, &impl->pool), "vkCreateCommandPool");
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = impl->pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    checkVk(device->vk.vkAllocateCommandBuffers(device->device, &alloc, &impl->commandBuffer), "vkAllocateCommandBuffers");
    if (impl->reusable) {
        // The command buffer owns the pool: it may still be executing when the encoder goes.
        auto cb = std::make_shared<CommandBufferImpl>();
        cb->device = device;
        cb->label = label;
        cb->pool = impl->pool;
        cb->commandBuffer = impl->commandBuffer;
        impl->pool = VK_NULL_HANDLE;
        impl->reusableBuffer = std::move(cb);
    }
    beginRecording(*device, impl->commandBuffer, impl->reusable);
    return impl;
}

namespace {

void checkQueryIndex(const QuerySetImpl& set, uint32_t index) {
    if (index >= set.count)
        fail(ErrorKind::InvalidArgument, "query index " + std::to_string(index) + " is outside query set '" + set.label +
                                             "' (" + std::to_string(set.count) + " queries)");
}

void recordTimestamp(CommandEncoderImpl& enc, const std::shared_ptr<QuerySetImpl>& set, uint32_t index) {
    checkQueryIndex(*set, index);
    // A query must be reset before it is written; resetting here keeps query sets
    // reusable frame after frame without the caller tracking them.
    enc.device->vk.vkCmdResetQueryPool(enc.commandBuffer, set->pool, index, 1);
    // ALL_COMMANDS: the tick is taken when everything recorded before has finished,
    // so a pass's begin..end spans its own work and not the wait for earlier passes.
    enc.device->vk.vkCmdWriteTimestamp2(enc.commandBuffer, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, set->pool, index);
    enc.retain(set);
}

} // namespace
} // namespace detail

using namespace detail;

CommandEncoder Device::createCommandEncoder(const CommandEncoderDesc& desc) const {
    checked(impl_, "Device");
    return CommandEncoder(makeEncoder(impl_, desc.label, VK_NULL_HANDLE, desc.reusable, desc.trackLifetimes));
}

ComputePassEncoder CommandEncoder::beginComputePass(const ComputePassDesc& desc) {
    auto* enc = checked(impl_, "CommandEncoder");
    enc->requireOutsidePass("beginComputePass");
    const auto& ts = desc.timestampWrites;
    if (ts.querySet) {
        auto set = ts.querySet.shared();
        if (!enc->device->info.limits.timestampsSupported)
            fail(ErrorKind::Unsupported, "compute pass '" + desc.label + "' asks for timestamps, but adapter '" +
                                             enc->device->info.name + "' has none on its compute queue");
        checkQueryIndex(*set, ts.endIndex);
        if (ts.beginIndex == ts.endIndex)
            fail(ErrorKind::InvalidArgument, "compute pass '" + desc.label + "' uses query " +
                                                 std::to_string(ts.beginIndex) + " for both its begin and end timestamps");
        recordTimestamp(*enc, set, ts.beginIndex);
        enc->passQueries = set;
        enc->passEndQuery = ts.endIndex;
    }
    enc->inPass = true;
    enc->passLabel = desc.label;
    enc->pipeline.reset();
    enc->boundGroups.clear();
    enc->pushConstantBytesSet = 0;
    return ComputePassEncoder(enc);
}

void ComputePassEncoder::setPipeline(const ComputePipeline& pipeline) {
    auto* enc = encoder_;
    if (!enc || !enc->inPass) fail(ErrorKind::InvalidArgument, "setPipeline on a compute pass that has ended");
    auto impl = pipeline.shared();
    checked(impl, "ComputePipeline");
    enc->device->vk.vkCmdBindPipeline(enc->commandBuffer, VK_PIPELINE_BIND_POINT_COMPUTE, impl->pipeline);
    // Vulkan keeps compatible descriptor sets across pipeline switches; hush asks for
    // them again so that what a dispatch reads is always what the caller set.
    enc->pipeline = impl;
    enc->boundGroups.assign(impl->setLayouts.size(), nullptr);
    enc->pushConstantBytesSet = 0;
    enc->retain(impl);
}

void ComputePassEncoder::setBindGroup(uint32_t index, const BindGroup& group) {
    auto* enc = encoder_;
    if (!enc || !enc->inPass) fail(ErrorKind::InvalidArgument, "setBindGroup on a compute pass that has ended");
    if (!enc->pipeline)
        fail(ErrorKind::InvalidArgument, "setBindGroup in compute pass '" + enc->passLabel + "' before setPipeline");
    auto impl = group.shared();
    checked(impl, "BindGroup");
    const auto& p = *enc->pipeline;
    if (index >= p.setLayouts.size())
        fail(ErrorKind::BindingMismatch, "bind group '" + impl->label + "' set at index " + std::to_string(index) +
                                             ", but pipeline '" + p.label + "' has " +
                                             std::to_string(p.setLayouts.size()) + " bind group layouts");
    const auto& expected = p.setLayouts[index];
    if (impl->layout != expected && impl->layout->entries != expected->entries)
        fail(ErrorKind::BindingMismatch, "bind group '" + impl->label + "' (made for " + impl->layout->origin +
                                             ") does not match pipeline '" + p.label + "' set " + std::to_string(index) +
                                             " (" + expected->origin + ")");
    enc->device->vk.vkCmdBindDescriptorSets(enc->commandBuffer, VK_PIPELINE_BIND_POINT_COMPUTE, p.layout, index, 1,
                                            &impl->set, 0, nullptr);
    enc->boundGroups[index] = impl;
    enc->retain(impl);
}

void ComputePassEncoder::setPushConstants(const void* data, uint32_t bytes, uint32_t offset) {
    auto* enc = encoder_;
    if (!enc || !enc->inPass) fail(ErrorKind::InvalidArgument, "setPushConstants on a compute pass that has ended");
    if (!enc->pipeline)
        fail(ErrorKind::InvalidArgument, "setPushConstants in compute pass '" + enc->passLabel + "' before setPipeline");
    const auto& p = *enc->pipeline;
    if (bytes == 0 || offset % 4 || bytes % 4 || offset + bytes > p.pushConstantBytes)
        fail(ErrorKind::InvalidArgument, "push constants [" + std::to_string(offset) + ", " + std::to_string(offset + bytes) +
                                             ") for pipeline '" + p.label + "', which takes " +
                                             std::to_string(p.pushConstantBytes) + " bytes (4-byte aligned)");
    enc->device->vk.vkCmdPushConstants(enc->commandBuffer, p.layout, VK_SHADER_STAGE_COMPUTE_BIT, offset, bytes, data);
    enc->pushConstantBytesSet = std::max(enc->pushConstantBytesSet, offset + bytes);
}

void ComputePassEncoder::setPushConstants(const PushConstants& values) {
    auto* enc = encoder_;
    if (!enc || !enc->inPass) fail(ErrorKind::InvalidArgument, "setPushConstants on a compute pass that has ended");
    if (!enc->pipeline || enc->pipeline.get() != values.pipeline().shared().get())
        fail(ErrorKind::InvalidArgument, "setPushConstants in compute pass '" + enc->passLabel + "': the values are for pipeline '" +
                                             (values.pipeline() ? values.pipeline().label() : std::string("(none)")) +
                                             "', which is not the bound one");
    values.requireComplete();
    if (values.size() > 0) setPushConstants(values.data(), values.size());
}

namespace {
// What every dispatch needs bound before it runs.
void requireReadyToDispatch(const CommandEncoderImpl* enc) {
    if (!enc || !enc->inPass) fail(ErrorKind::InvalidArgument, "dispatch on a compute pass that has ended");
    if (!enc->pipeline) fail(ErrorKind::InvalidArgument, "dispatch in compute pass '" + enc->passLabel + "' before setPipeline");
    const auto& p = *enc->pipeline;
    for (uint32_t set = 0; set < p.setUsed.size(); ++set)
        if (p.setUsed[set] && !enc->boundGroups[set])
            fail(ErrorKind::BindingMismatch, "dispatch in compute pass '" + enc->passLabel + "': pipeline '" + p.label +
                                                 "' needs a bind group at set " + std::to_string(set) + ", none is set");
    if (enc->pushConstantBytesSet < p.shaderPushConstantBytes)
        fail(ErrorKind::InvalidArgument, "dispatch in compute pass '" + enc->passLabel + "': pipeline '" + p.label +
                                             "' reads " + std::to_string(p.shaderPushConstantBytes) +
                                             " bytes of push constants, " + std::to_string(enc->pushConstantBytesSet) +
                                             " were set");
}
} // namespace

void ComputePassEncoder::dispatchWorkgroups(uint32_t x, uint32_t y, uint32_t z) {
    auto* enc = encoder_;
    requireReadyToDispatch(enc);
    const auto& limits = enc->device->limits;
    if (x > limits.maxComputeWorkGroupCount[0] || y > limits.maxComputeWorkGroupCount[1] ||
        z > limits.maxComputeWorkGroupCount[2])
        fail(ErrorKind::Unsupported, "dispatch of " + std::to_string(x) + "x" + std::to_string(y) + "x" +
                                         std::to_string(z) + " workgroups in pass '" + enc->passLabel +
                                         "' exceeds the adapter's maxComputeWorkgroupCount");
    if (x == 0 || y == 0 || z == 0) return;
    enc->device->vk.vkCmdDispatch(enc->commandBuffer, x, y, z);
}

void ComputePassEncoder::dispatchWorkgroupsIndirect(const Buffer& buffer, uint64_t offset) {
    auto* enc = encoder_;
    requireReadyToDispatch(enc);
    if (!buffer) fail(ErrorKind::InvalidArgument, "indirect dispatch in pass '" + enc->passLabel + "' without a buffer");
    const auto& desc = buffer.impl()->desc;
    if (!hasAny(desc.usage, BufferUsage::Indirect))
        fail(ErrorKind::InvalidArgument, "indirect dispatch in pass '" + enc->passLabel + "': buffer '" + desc.label +
                                             "' was not created with BufferUsage::Indirect");
    if (offset % 4 != 0 || offset + 12 > desc.size)
        fail(ErrorKind::InvalidArgument, "indirect dispatch in pass '" + enc->passLabel + "': offset " +
                                             std::to_string(offset) + " of buffer '" + desc.label + "' (" +
                                             std::to_string(desc.size) + " bytes) does not hold 3 aligned uint32");
    enc->device->vk.vkCmdDispatchIndirect(enc->commandBuffer, buffer.impl()->buffer, offset);
    enc->retain(buffer.shared());
}

void ComputePassEncoder::dispatchThreads(uint32_t x, uint32_t y, uint32_t z) {
    if (!encoder_ || !encoder_->pipeline)
        fail(ErrorKind::InvalidArgument, "dispatchThreads before setPipeline");
    const auto size = encoder_->pipeline->workgroupSize;
    auto groups = [](uint32_t n, uint32_t s) { return (n + s - 1) / s; };
    dispatchWorkgroups(groups(x, size[0]), groups(y, size[1]), groups(z, size[2]));
}

void ComputePassEncoder::end() {
    auto* enc = encoder_;
    if (!enc || !enc->inPass) fail(ErrorKind::InvalidArgument, "end() on a compute pass that has already ended");
    enc->inPass = false;
    if (enc->passQueries) {
        recordTimestamp(*enc, enc->passQueries, enc->passEndQuery);
        enc->passQueries.reset();
    }
    enc->pipeline.reset();
    enc->boundGroups.clear();
    encoder_ = nullptr;
}

void CommandEncoder::resetQuerySet(const QuerySet& set, uint32_t first, uint32_t count) {
    auto* enc = checked(impl_, "CommandEncoder");
    enc->requireOutsidePass("resetQuerySet");
    auto impl = set.shared();
    checked(impl, "QuerySet");
    if (count == 0) return;
    checkQueryIndex(*impl, first + count - 1);
    enc->device->vk.vkCmdResetQueryPool(enc->commandBuffer, impl->pool, first, count);
    enc->retain(impl);
}

void CommandEncoder::writeTimestamp(const QuerySet& set, uint32_t index) {
    auto* enc = checked(impl_, "CommandEncoder");
    enc->requireOutsidePass("writeTimestamp");
    checked(set.shared(), "QuerySet");
    if (!enc->device->info.limits.timestampsSupported)
        fail(ErrorKind::Unsupported, "adapter '" + enc->device->info.name + "' has no timestamps on its compute queue");
    recordTimestamp(*enc, set.shared(), index);
}

CommandBuffer CommandEncoder::finish() {
    auto* enc = checked(impl_, "CommandEncoder");
    enc->requireOutsidePass("finish");
    enc->finished = true;
    if (enc->reusable) {
        const VkResult ended = enc->device->vk.vkEndCommandBuffer(enc->commandBuffer);
        if (ended < 0) checkVk(ended, "vkEndCommandBuffer for '" + enc->label + "'");
        auto& cb = enc->reusableBuffer;
        cb->submitted = false;
        cb->keepAlive.swap(enc->keepAlive);   // swap, not move: both keep their capacity
        return CommandBuffer(cb);
    }
    if (enc->external) {
        enc->keepAlive.clear();   // the engine owns the submission and the lifetimes
        return CommandBuffer();
    }
    auto out = std::make_shared<CommandBufferImpl>();
    out->device = enc->device;
    out->label = enc->label;
    out->external = enc->external;
    out->keepAlive = std::move(enc->keepAlive);
    out->commandBuffer = enc->commandBuffer;
    if (!enc->external) {
        checkVk(enc->device->vk.vkEndCommandBuffer(enc->commandBuffer), "vkEndCommandBuffer for '" + enc->label + "'");
        out->pool = enc->pool;   // the command buffer now owns the pool
        enc->pool = VK_NULL_HANDLE;
    }
    return CommandBuffer(std::move(out));
}

void CommandEncoder::reset() {
    auto* enc = checked(impl_, "CommandEncoder");
    if (!enc->reusable)
        fail(ErrorKind::InvalidArgument, "reset() on command encoder '" + enc->label +
                                             "', which was not created with reusable = true");
    auto& cb = *enc->reusableBuffer;
    if (cb.submitted && enc->device->completedValue() < cb.submission)
        fail(ErrorKind::InvalidArgument, "reset() on command encoder '" + enc->label + "' while submission " +
                                             std::to_string(cb.submission) + " still executes; wait for it first");
    if (enc->inPass) fail(ErrorKind::InvalidArgument, "reset() on command encoder '" + enc->label + "' with a pass open");
    checkVk(enc->device->vk.vkResetCommandPool(enc->device->device, cb.pool, 0), "vkResetCommandPool");
    cb.keepAlive.clear();
    cb.submitted = false;
    enc->keepAlive.clear();
    enc->finished = false;
    beginRecording(*enc->device, enc->commandBuffer, true);
}

const std::string& CommandBuffer::label() const { return checked(impl_, "CommandBuffer")->label; }

} // namespace hush::rhi
