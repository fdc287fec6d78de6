// Queue: submissions numbered on a timeline semaphore. A command buffer keeps what
// it uses alive until its submission completes.
#include "fault_injection_detail.hpp"
#include "objects.hpp"
#include "vk_check.hpp"

namespace hush::rhi {

using namespace detail;

SubmissionId Queue::submit(const CommandBuffer& commands) { return submit(std::span(&commands, 1)); }

SubmissionId Queue::submit(std::span<const CommandBuffer> commands) {
    auto* device = device_.get();
    // Submitting one command buffer (every frame) must not allocate.
    constexpr size_t kInline = 8;
    VkCommandBufferSubmitInfo inlineInfos[kInline];
    std::vector<VkCommandBufferSubmitInfo> heapInfos;
    if (commands.size() > kInline) heapInfos.resize(commands.size());
    VkCommandBufferSubmitInfo* infos = commands.size() > kInline ? heapInfos.data() : inlineInfos;
    size_t count = 0;
    for (const auto& cb : commands) {
        auto* impl = checked(cb.shared(), "CommandBuffer");
        if (impl->external)
            fail(ErrorKind::InvalidArgument, "command buffer '" + impl->label +
                                                 "' records into an engine's VkCommandBuffer; the engine submits it");
        if (impl->submitted)
            fail(ErrorKind::InvalidArgument, "command buffer '" + impl->label + "' was already submitted; record a new one");
        if (impl->device.get() != device)
            fail(ErrorKind::InvalidArgument, "command buffer '" + impl->label + "' belongs to another device");
        VkCommandBufferSubmitInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
        info.commandBuffer = impl->commandBuffer;
        infos[count++] = info;
    }

    std::lock_guard lock(device->queueMutex);
    device->retireCompleted();
    const SubmissionId id = device->lastSubmitted + 1;
    VkSemaphoreSubmitInfo signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    signal.semaphore = device->timeline;
    signal.value = id;
    signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    submit.commandBufferInfoCount = uint32_t(count);
    submit.pCommandBufferInfos = infos;
    submit.signalSemaphoreInfoCount = 1;
    submit.pSignalSemaphoreInfos = &signal;
    VkResult result = VK_ERROR_DEVICE_LOST;
    if (!device->lost && !takeInjectedFault(InjectedFault::DeviceLost))
        result = device->vk.vkQueueSubmit2(device->queue, 1, &submit, VK_NULL_HANDLE);
    if (result == VK_ERROR_DEVICE_LOST) device->lost = true;
    checkVk(result, "vkQueueSubmit2");
    device->lastSubmitted = id;

    InFlight& flight = device->inFlight.emplace_back();
    flight.id = id;
    for (const auto& cb : commands) {
        cb.impl()->submitted = true;
        cb.impl()->submission = id;
        if (!flight.first) flight.first = cb.shared();
        else flight.more.push_back(cb.shared());
    }
    return id;
}

void Queue::wait(SubmissionId id) {
    auto* device = device_.get();
    if (id > device->lastSubmitted)
        fail(ErrorKind::InvalidArgument, "waiting for submission " + std::to_string(id) + ", but only " +
                                             std::to_string(device->lastSubmitted) + " were submitted");
    VkSemaphoreWaitInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_WAIT_INFO};
    info.semaphoreCount = 1;
    info.pSemaphores = &device->timeline;
    info.pValues = &id;
    const VkResult result =
        device->lost ? VK_ERROR_DEVICE_LOST : device->vk.vkWaitSemaphores(device->device, &info, UINT64_MAX);
    if (result == VK_ERROR_DEVICE_LOST) device->lost = true;
    checkVk(result, "waiting for submission");
    std::lock_guard lock(device->queueMutex);
    device->retireCompleted();
}

void Queue::waitIdle() {
    SubmissionId last;
    {
        std::lock_guard lock(device_->queueMutex);
        last = device_->lastSubmitted;
    }
    if (last > 0) wait(last);
}

bool Queue::isComplete(SubmissionId id) const { return device_->completedValue() >= id; }

SubmissionId Queue::lastSubmitted() const {
    std::lock_guard lock(device_->queueMutex);
    return device_->lastSubmitted;
}

} // namespace hush::rhi
