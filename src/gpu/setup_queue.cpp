#include "gpu/setup_queue.h"

namespace gpu {

SetupQueue::~SetupQueue() {
    // Never recorded, or recorded and the owner destroys the library: either way nothing on the GPU
    // can still read these once the owner destroys what it lent (it waits for its device first).
    releaseRecorded();
    for (Step& step : steps_)
        if (step.release) step.release();
}

void SetupQueue::add(Record record, Release release) { steps_.push_back({std::move(record), std::move(release)}); }

void SetupQueue::recordInto(VkCommandBuffer cmd) {
    for (Step& step : steps_) {
        step.record(cmd);
        // Steps may write what a later step reads (a cleared buffer, a baked image before its mips).
        recordFullBarrier(cmd);
        if (step.release) recorded_.push_back(std::move(step.release));
    }
    steps_.clear();
}

void SetupQueue::releaseRecorded() {
    for (Release& release : recorded_) release();
    recorded_.clear();
}

void recordFullBarrier(VkCommandBuffer cmd) {
    VkMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    barrier.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    barrier.srcAccessMask = VK_ACCESS_2_MEMORY_WRITE_BIT;
    barrier.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT | VK_PIPELINE_STAGE_2_HOST_BIT;
    barrier.dstAccessMask = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT | VK_ACCESS_2_HOST_READ_BIT;
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.memoryBarrierCount = 1;
    dependency.pMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(cmd, &dependency);
}

}  // namespace gpu
