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

namespace gpu { class VulkanContext; }

namespace render {

// Where bone matrices come from: CPU jobs uploaded each frame (the reference), or the GPU passes.
enum class AnimationPath { Cpu, Gpu };
const char* animationPathName(AnimationPath path);
// "cpu", "gpu"; false for anything else.
bool parseAnimationPath(const std::string& name, AnimationPath& path);

class AnimationPass {
public:
    AnimationPass(const gpu::VulkanContext& context, const crowd::Crowd& crowd, const CrowdBuffers& buffers,
                  const DrawLists& lists, std::uint32_t framesInFlight);
    ~AnimationPass();
    AnimationPass(const AnimationPass&) = delete;
    AnimationPass& operator=(const AnimationPass&) = delete;

    // Uploads the segments the crowd changed since this pass last looked (all of them when it missed a
    // generation), then runs the motion pass for `time`. The records are ready for culling after it.
    void recordMotion(VkCommandBuffer cmd, std::uint32_t frameSlot, double time);
    // After culling: the bones of every listed character, ready for skinning and drawing.
    void recordPalettes(VkCommandBuffer cmd);

    // The bones were reallocated (CrowdBuffers::setBoneBlocks): the palette pass writes the new buffer.
    void rebindBones(const CrowdBuffers& buffers);

    // Uploads the segments the crowd changed since this pass last looked, without the motion pass (the
    // event pass reads them on the CPU animation path too). recordMotion does this first.
    void recordSegmentUpload(VkCommandBuffer cmd, std::uint32_t frameSlot) { uploadSegments(cmd, frameSlot); }

    // The flattened clip library's tables on the device (anim::ClipLibrary's, in its order), and each
    // character's current motion segment: what the event pass reads beside the motion pass.
    enum class Table : std::uint32_t { Models = 0, Joints, Clips, Tracks, KeyTimes, KeyValues, RootSamples };
    const gpu::Buffer& libraryBuffer(Table table) const { return library_[static_cast<std::uint32_t>(table)]; }
    const gpu::Buffer& motions() const { return motions_; }

    // Device bytes: the library (once per crowd) and the segments (64 per character).
    std::uint64_t libraryBytes() const { return libraryBytes_; }
    std::uint64_t segmentBytes() const { return motions_.size; }

private:
    static constexpr std::uint64_t kNothing = ~0ull;
    void uploadSegments(VkCommandBuffer cmd, std::uint32_t frameSlot);
    void release();

    const gpu::VulkanContext& context_;
    const crowd::Crowd& crowd_;
    const DrawLists& lists_;
    std::vector<gpu::Buffer> library_;
    std::uint64_t libraryBytes_ = 0;
    gpu::Buffer motions_, dispatches_;
    // Per frame in flight: replanned segments, then their characters' indices (after the segments).
    std::vector<gpu::Buffer> staging_;
    std::vector<std::unique_ptr<gpu::DescriptorBundle>> scatterSets_;
    std::uint64_t uploadedGeneration_ = kNothing;
    std::unique_ptr<gpu::DescriptorBundle> motionSet_, paletteSet_;
    VkPipelineLayout motionLayout_ = VK_NULL_HANDLE, paletteLayout_ = VK_NULL_HANDLE, scatterLayout_ = VK_NULL_HANDLE;
    VkPipeline motion_ = VK_NULL_HANDLE, paletteDispatch_ = VK_NULL_HANDLE, scatter_ = VK_NULL_HANDLE;
    // The palette pass for models of up to 64 joints, and for larger ones (more shared memory).
    VkPipeline palette_ = VK_NULL_HANDLE, paletteLarge_ = VK_NULL_HANDLE;
};

}  // namespace render
