#pragma once
// Animation on the GPU. The crowd's clip library is uploaded once; each frame only the motion
// segments the CPU replanned go up. Two compute passes then do the rest:
//   motion (before culling, every character): its segment at this frame's time -> its record's
//     placement, clips and phase, so culling sees where everyone is;
//   palette (after culling, the characters culling listed): sample, blend, hierarchy -> bone matrices
//     in the buffer every skinning method reads. Off-screen characters get no palette; their motion
//     is a closed form, so nothing about them goes stale.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "crowd/crowd.h"
#include "gpu/buffer.h"
#include "gpu/descriptor_bundle.h"
#include "render/crowd_buffers.h"
#include "render/draw_lists.h"
#include "render/driven_pass.h"
#include "render/terrain_buffer.h"

namespace gpu { class VulkanContext; }

namespace render {

// Where bone matrices come from: CPU jobs uploaded each frame (the reference), or the GPU passes.
enum class AnimationPath { Cpu, Gpu };
const char* animationPathName(AnimationPath path);
// "cpu", "gpu"; false for anything else.
bool parseAnimationPath(const std::string& name, AnimationPath& path);

class AnimationPass {
public:
    // Uploads `crowd`'s clip library; the pass then animates any crowd of the same layout
    // (crowd::Crowd::layoutKey), handed to each frame.
    AnimationPass(const gpu::VulkanContext& context, const crowd::Crowd& crowd, CrowdBuffers& buffers,
                  const DrawLists& lists, const TerrainBuffer& terrain, std::uint32_t framesInFlight);
    ~AnimationPass();
    AnimationPass(const AnimationPass&) = delete;
    AnimationPass& operator=(const AnimationPass&) = delete;

    // Uploads the segments and identities (tint, scale, props; a free slot's scale 0) of the slots
    // `crowd` changed after generation `since` (every slot for crowd::ChangeLog::kEverything:
    // render/frame_ledger.h), on either animation path (the event pass reads the segments). The CPU's
    // copy of the records (CrowdBuffers::mutableRecords) gets the identities too.
    void recordSegmentUpload(VkCommandBuffer cmd, std::uint32_t frameSlot, const crowd::Crowd& crowd, std::uint64_t since);
    // After the upload, with the host's device samples this frame: their keys (render/driven_pass.h).
    void recordDeviceSamples(VkCommandBuffer cmd, std::uint32_t frameSlot, const crowd::Crowd& crowd,
                             const DeviceSampleInput& samples, double time) {
        driven_->recordIngest(cmd, frameSlot, crowd, samples, time);
    }
    // After the upload: the motion pass for `time`. The records are ready for culling after it.
    void recordMotion(VkCommandBuffer cmd, const crowd::Crowd& crowd, double time);
    const DrivenPass& driven() const { return *driven_; }
    void checkDeviceSamples(const DeviceSampleInput& samples) const { driven_->checkSamples(samples); }
    // After culling: the bones of every listed character, ready for skinning and drawing.
    void recordPalettes(VkCommandBuffer cmd);

    // The bones were reallocated (CrowdBuffers::setBoneBlocks): the palette pass writes the new buffer.
    void rebindBones(const CrowdBuffers& buffers);


    // The flattened clip library's tables on the device (anim::ClipLibrary's, in its order), and each
    // character's current motion segment: what the event pass reads beside the motion pass.
    enum class Table : std::uint32_t { Models = 0, Joints, Clips, Tracks, KeyTimes, KeyValues, RootSamples };
    const gpu::Buffer& libraryBuffer(Table table) const { return library_[static_cast<std::uint32_t>(table)]; }
    const gpu::Buffer& motions() const { return motions_; }

    // Device bytes: the library (once per crowd) and the segments (64 per character).
    std::uint64_t libraryBytes() const { return libraryBytes_; }
    std::uint64_t segmentBytes() const { return motions_.size; }

private:
    void scatterSegments(VkCommandBuffer cmd, std::uint32_t frameSlot, std::uint32_t count);
    void recordKeyUpload(VkCommandBuffer cmd, std::uint32_t frameSlot, const crowd::Crowd& crowd, std::uint64_t since);
    void release();

    const gpu::VulkanContext& context_;
    CrowdBuffers& buffers_;
    const DrawLists& lists_;
    std::vector<std::uint32_t> modelJoints_;  // per model of the layout
    std::vector<gpu::Buffer> library_;
    std::uint64_t libraryBytes_ = 0;
    gpu::Buffer motions_, dispatches_;
    // Per frame in flight: the changed slots' segments, their indices, their identities (tint and
    // scale; props and generation), their key counts, each array after the one before.
    std::vector<gpu::Buffer> staging_;
    VkDeviceSize indicesOffset_ = 0, tintsOffset_ = 0, wordsOffset_ = 0, countsOffset_ = 0;
    std::unique_ptr<DrivenPass> driven_;
    std::vector<std::unique_ptr<gpu::DescriptorBundle>> scatterSets_;
    std::unique_ptr<gpu::DescriptorBundle> motionSet_, paletteSet_;
    VkPipelineLayout motionLayout_ = VK_NULL_HANDLE, paletteLayout_ = VK_NULL_HANDLE, scatterLayout_ = VK_NULL_HANDLE;
    VkPipeline motion_ = VK_NULL_HANDLE, paletteDispatch_ = VK_NULL_HANDLE, scatter_ = VK_NULL_HANDLE;
    // The palette pass for models of up to 64 joints, and for larger ones (more shared memory).
    VkPipeline palette_ = VK_NULL_HANDLE, paletteLarge_ = VK_NULL_HANDLE;
};

}  // namespace render
