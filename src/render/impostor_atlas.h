#pragma once
// The impostor atlas: every model of a crowd, skinned by the engine in every clip at `framesPerClip`
// phases and seen from azimuths x elevations over the upper hemisphere (render/impostor_cell.h),
// rendered into cells of two RGBA8 texture arrays: albedo (sRGB; palette x base-colour texture,
// untinted) and the model-space normal, each with coverage in alpha and a mip chain of box-filtered
// levels. The usual sampler stops at 8-texel cells; a second one, for the far crowd's smallest
// impostors, reaches the whole chain, down to 1-texel cells. Baked once at load time on the GPU (one
// command buffer, one draw per cell), bounded in memory by ImpostorSettings::budgetPerModel.
//
// A cell shows the square, in the view's image plane, that holds the model's pose sphere: so every
// pose of every clip fits, and an impostor is a quad over the character's pose sphere.
//
// A model has a set of cells for each props mask its characters carry (render/impostor_prop_sets.h,
// up to IMPOSTOR_SETS), each captured with those props. A set whose props reach beyond the pose sphere
// (the soldier's flag, up to 0.65 m) frames its cells by a larger square about the same centre
// (crowd::poseRadiusAbout), so its quads are larger and the flag is not clipped.
#include <cstdint>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/buffer.h"
#include "gpu_types.h"
#include "model/skinned_model.h"
#include "render/geometry_pool.h"

namespace gpu { class VulkanContext; }

namespace render {

struct ImpostorSettings {
    std::uint32_t azimuths = 16;
    std::uint32_t elevations = 4;
    std::uint32_t framesPerClip = 16;   // halved (down to 4), then cells shrunk, until a model fits the budget
    std::uint32_t cellSize = 64;        // texels per side of a cell
    std::uint64_t budgetPerModel = 256ull << 20;  // bytes of both arrays, mips included, every cell set of the
                                                  // model: over it the rarest sets go first, then frames
};

// The cells, frames and cell size the atlas will have for these models: what the constructor bakes
// and the memory check counts (bytes of both arrays with their mips).
struct ImpostorPlan {
    // The GPU's table: IMPOSTOR_SETS entries a model, model m's set s at m x IMPOSTOR_SETS + s (cells.w
    // sets; the entries past them repeat set 0). Squares are the pose spheres' until the atlas widens them.
    std::vector<gpu::ImpostorModel> models;
    std::uint32_t cellSize = 0;
    std::uint32_t mipLevels = 0;      // down to a texel a cell (the far crowd's second sampler)
    std::uint32_t sampledLevels = 0;  // of those, the ones filtered reads reach (8 texels a cell and more)
    std::uint32_t cellsPerRow = 0;
    std::uint32_t layers = 0;
    std::uint64_t bytes() const;
    std::uint64_t bytesOf(std::uint32_t model) const;  // the model's share (its cells, every set)
    std::uint32_t modelCount() const { return static_cast<std::uint32_t>(models.size() / IMPOSTOR_SETS); }
    const gpu::ImpostorModel& set(std::uint32_t model, std::uint32_t s) const { return models[model * IMPOSTOR_SETS + s]; }
    std::uint32_t setCount(std::uint32_t model) const { return set(model, 0).cells.w; }
};
// `propSets`: per model, the props masks to give cell sets, most carried first (impostorPropSets); the
// budget may keep fewer.
ImpostorPlan planImpostors(std::span<const model::SkinnedModel* const> models, std::span<const gpu::ModelRecord> records,
                           std::span<const std::vector<std::uint32_t>> propSets, const ImpostorSettings& settings);

class ImpostorAtlas {
public:
    // Bakes the atlas (waits for the GPU). `sceneSet` (layout `sceneSetLayout`) must hold the pool's
    // palette and textures; only the bake reads it. Throws gpu::Error when the atlas cannot be allocated.
    // `propSets` as planImpostors takes them.
    ImpostorAtlas(const gpu::VulkanContext& context, const GeometryPool& pool,
                  std::span<const model::SkinnedModel* const> models, std::span<const std::vector<std::uint32_t>> propSets,
                  VkDescriptorSetLayout sceneSetLayout, VkDescriptorSet sceneSet, const ImpostorSettings& settings = {});
    ~ImpostorAtlas();
    ImpostorAtlas(const ImpostorAtlas&) = delete;
    ImpostorAtlas& operator=(const ImpostorAtlas&) = delete;

    const ImpostorPlan& plan() const { return plan_; }
    const std::vector<gpu::ImpostorModel>& models() const { return plan_.models; }
    const gpu::Buffer& modelTable() const { return modelTable_; }
    // Set 2 of the impostor draw: binding 0 the albedo array, 1 the normal array (fragment stage).
    VkDescriptorSetLayout setLayout() const { return setLayout_; }
    VkDescriptorSet set() const { return set_; }
    VkDeviceSize bytes() const;
    double bakeMs() const { return bakeMs_; }

private:
    struct Layer;
    void createImages();
    void createSamplingSet();
    void bake(const GeometryPool& pool, std::span<const model::SkinnedModel* const> models,
              VkDescriptorSetLayout sceneSetLayout, VkDescriptorSet sceneSet);
    void release();

    const gpu::VulkanContext& context_;
    ImpostorPlan plan_;
    VkImage images_[2] = {};
    VkDeviceMemory memory_[2] = {};
    VkDeviceSize imageBytes_[2] = {};
    VkImageView arrayViews_[2] = {};
    VkSampler sampler_ = VK_NULL_HANDLE;            // filtered reads, down to 8 texels a cell
    VkSampler wholeChainSampler_ = VK_NULL_HANDLE;  // every level (the far layer's reads)
    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkDescriptorPool descriptorPool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    gpu::Buffer modelTable_;
    double bakeMs_ = 0.0;
};

// The bone matrices of every pose the atlas captures, model after model, set after set (its props
// carried, the others collapsed), clip after clip, frame after frame (identity placement: the model's
// own space); `firstBone[m x IMPOSTOR_SETS + s]` is where model m's set s's poses begin.
std::vector<gpu::BoneRows> impostorPoses(std::span<const model::SkinnedModel* const> models,
                                         std::span<const gpu::ImpostorModel> plan, std::vector<std::uint32_t>& firstBone);

// Widens each set's square (w) to hold the poses with its props about the pose sphere's centre, for
// sets carrying a prop the pose sphere leaves out (crowd::poseRadiusAbout); never below the sphere.
void frameImpostorSets(std::span<const model::SkinnedModel* const> models, ImpostorPlan& plan);

}  // namespace render
