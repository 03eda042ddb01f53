#pragma once
// The draw pass of the characters: it consumes what a skinning method produced. Methods that skin
// before drawing leave world-space vertices in a buffer, drawn with one vkCmdDrawIndexedIndirectCount
// over the compacted list culling wrote; the vertex-shader methods leave nothing, and the draw skins
// the bind pose as it goes: the paper's baseline with one draw per character slot and its bones at a
// dynamic uniform offset, or one instanced draw per (model, LOD) bucket. A later pass (shadows, an
// impostor capture) consumes the same inputs the same way.
#include <cstdint>
#include <memory>

#include <vulkan/vulkan.h>

#include "gpu/buffer.h"
#include "gpu/descriptor_bundle.h"
#include "gpu/pipeline.h"
#include "render/crowd_buffers.h"
#include "render/draw_lists.h"
#include "render/geometry_pool.h"
#include "render/scene_pass.h"

#include "render/target_format.h"

namespace gpu { class VulkanContext; }

namespace render {

enum class DrawInput {
    SkinnedVertices,          // world-space positions and normals in a buffer (SkinnedVertices)
    BindPosePerCharacter,     // skin in the vertex shader, one draw per character (the paper's baseline)
    BindPoseInstanced,        // skin in the vertex shader, one instanced draw per bucket
};

// Where a method left the skinned vertices: positions (RGBA32F) at the start of the buffer, normals
// (xyz, material in w) at normalsOffset; vertex i of a draw is at vertexOffset + i in both.
struct SkinnedVertices {
    const gpu::Buffer* buffer = nullptr;
    VkDeviceSize normalsOffset = 0;
};

class CharacterDraw {
public:
    CharacterDraw(const gpu::VulkanContext& context, const GeometryPool& pool, const CrowdBuffers& crowd,
                  const DrawLists& lists, VkDescriptorSetLayout sceneSetLayout, const TargetFormat& target);
    ~CharacterDraw();
    CharacterDraw(const CharacterDraw&) = delete;
    CharacterDraw& operator=(const CharacterDraw&) = delete;

    // What a draw renders into: the colour pass's target, or the shadow map (depth only).
    enum class Target { Colour, ShadowMap };
    // Records the characters' draws inside a rendering pass whose scene set is `sceneSet` (for the
    // shadow map: the scene set seen from the light). `fades` (colour pass, skinned vertices): the
    // culling wrote fades (gpu_types.h, FADE_SHIFT), so characters fading into their impostors are
    // drawn dithered from their own list (those fading between mesh levels were morphed while skinned).
    void record(VkCommandBuffer cmd, DrawInput input, const SkinnedVertices& vertices, VkDescriptorSet sceneSet,
                const ScenePush& push, Target target = Target::Colour, bool fades = false) const;

    // The bones were reallocated (CrowdBuffers::setBoneBlocks): both sets bind the new buffer.
    void rebindBones();

private:
    void createPipelines(VkDescriptorSetLayout sceneSetLayout, const TargetFormat& target);
    // The three pipelines (skinned, per character, instanced) for one target's formats.
    void createPipelines(gpu::GraphicsPipelineDesc desc, VkPipeline (&pipelines)[3]);
    void release();
    void bindCommon(VkCommandBuffer cmd, VkPipeline pipeline, VkDescriptorSet sceneSet, const ScenePush& push) const;

    const gpu::VulkanContext& context_;
    const GeometryPool& pool_;
    const CrowdBuffers& crowd_;
    const DrawLists& lists_;
    std::unique_ptr<gpu::DescriptorBundle> crowdSet_;   // set 1: models, characters, visible lists, bones, states
    std::unique_ptr<gpu::DescriptorBundle> boneBlock_;  // set 2: one character's bones (dynamic offset)
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline colour_[3] = {};  // by DrawInput
    VkPipeline shadow_[3] = {};
    VkPipeline intoImpostor_ = VK_NULL_HANDLE;  // skinned vertices, colour: a mesh fading into its impostor, dithered
};

}  // namespace render
