#pragma once
// What both fragment-shader methods share: the pass-1 pipeline whose instances are the buckets'
// rectangles (shaders/skin_fragment.vert.glsl) and its bindings. The methods differ in where the
// fragments go: RGBA32F attachments then a copy ("two-pass"), or storage writes ("two-pass-direct").
#include <memory>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/descriptor_bundle.h"
#include "skin/skin_target_layout.h"
#include "skin/skinned_vertex_buffer.h"
#include "skin/skinning_method.h"

namespace skin {

class FragmentSkinPass {
public:
    FragmentSkinPass(const MethodSetup& setup, const SkinnedVertexBuffer& skinned,
                     std::span<const std::uint32_t> fragmentShader, std::vector<VkFormat> colorFormats);
    ~FragmentSkinPass();
    FragmentSkinPass(const FragmentSkinPass&) = delete;
    FragmentSkinPass& operator=(const FragmentSkinPass&) = delete;

    const SkinTargetLayout& layout() const { return layout_; }
    // Inside a rendering of tile `tile`'s extent: every bucket's rectangle, a draw each (its instance
    // index the bucket), by the pipeline with or without the morph its level needs.
    void recordTile(VkCommandBuffer cmd, std::uint32_t tile) const;

private:
    void release();

    const gpu::VulkanContext& context_;
    std::uint32_t bucketCount_;
    SkinTargetLayout layout_;
    std::unique_ptr<gpu::DescriptorBundle> descriptors_;
    VkPipelineLayout pipelineLayout_ = VK_NULL_HANDLE;
    VkPipeline pipelines_[2] = {};    // [1]: with the morph into a coarser level (shaders/lod_morph.glsl.inc)
    std::vector<bool> bucketMorphs_;  // per bucket: its level has a coarser mesh level
};

}  // namespace skin
