#include "render/frame_ledger.h"

#include <cstring>

#include "crowd/change_log.h"
#include "gpu/barriers.h"
#include "gpu/vulkan_context.h"

namespace render {

FrameLedger::FrameLedger(const gpu::VulkanContext& context, std::uint32_t framesInFlight)
    : context_(context), slots_(framesInFlight), through_(crowd::ChangeLog::kEverything) {
    words_ = gpu::createBuffer(context, framesInFlight * sizeof(std::uint32_t), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                               gpu::MemoryUse::HostReadback, "frame ledger");
    std::memset(words_.mapped, 0, framesInFlight * sizeof(std::uint32_t));
}

FrameLedger::~FrameLedger() { gpu::destroyBuffer(context_, words_); }

FrameLedger::Uploads FrameLedger::begin(VkCommandBuffer cmd, std::uint32_t slot, std::uint64_t crowdId,
                                        std::uint64_t sealed) {
    SlotFrame& frame = slots_[slot];
    std::uint32_t word = 0;
    std::memcpy(&word, static_cast<const std::byte*>(words_.mapped) + slot * sizeof word, sizeof word);
    std::uint64_t since = through_;
    bool resend = false;
    if (word != frame.number) {
        // The frame last recorded in this slot never ran: what it uploaded goes again.
        since = frame.from;
        resend = true;
        ++lost_;
    }
    if (crowdId != crowdId_) since = crowd::ChangeLog::kEverything, resend = true;
    crowdId_ = crowdId;
    through_ = sealed;
    // 0 is what a word holds before any frame ran, so a frame's number is never 0.
    if (++next_ == 0) ++next_;
    frame = {next_, since};
    // After the slot's previous write (the host has waited for it; this orders it for the GPU too).
    constexpr gpu::Access fill{VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT};
    gpu::memoryBarrier(cmd, fill, fill);
    vkCmdFillBuffer(cmd, words_.buffer, slot * sizeof(std::uint32_t), sizeof(std::uint32_t), next_);
    gpu::memoryBarrier(cmd, fill, {VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT});
    return {since, resend};
}

}  // namespace render
