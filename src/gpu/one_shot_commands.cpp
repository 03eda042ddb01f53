#include "gpu/one_shot_commands.h"

#include "gpu/setup_queue.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"

namespace gpu {

void runOneShot(const VulkanContext& context, std::function<void(VkCommandBuffer)> record,
                std::function<void()> release) {
    if (SetupQueue* deferred = context.deferredSetup()) {
        deferred->add(std::move(record), std::move(release));
        return;
    }
    try {
        runOneShotNow(context, record);
    } catch (...) {
        if (release) release();
        throw;
    }
    if (release) release();
}

void runOneShotNow(const VulkanContext& context, const std::function<void(VkCommandBuffer)>& record) {
    if (!context.commandPool) throw Error("internal: a submission on a borrowed device");
    VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocate.commandPool = context.commandPool;
    allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocate.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VK_CHECK(vkAllocateCommandBuffers(context.device, &allocate, &cmd));
    VkFence fence = VK_NULL_HANDLE;
    try {
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
        record(cmd);
        // Make every write of this submission available to whatever comes next, host included.
        recordFullBarrier(cmd);
        VK_CHECK(vkEndCommandBuffer(cmd));

        VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        VK_CHECK(vkCreateFence(context.device, &fenceInfo, nullptr, &fence));
        VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        submit.commandBufferCount = 1;
        submit.pCommandBuffers = &cmd;
        VK_CHECK(vkQueueSubmit(context.queue, 1, &submit, fence));
        VK_CHECK(vkWaitForFences(context.device, 1, &fence, VK_TRUE, UINT64_MAX));
    } catch (...) {
        if (fence) vkDestroyFence(context.device, fence, nullptr);
        vkFreeCommandBuffers(context.device, context.commandPool, 1, &cmd);
        throw;
    }
    vkDestroyFence(context.device, fence, nullptr);
    vkFreeCommandBuffers(context.device, context.commandPool, 1, &cmd);
}

}  // namespace gpu
