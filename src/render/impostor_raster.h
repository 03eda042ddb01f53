#pragma once
// The compute rasterizer of impostors (docs/compute-raster.md). After culling, one compute pass
// rasterizes the frame's impostors into a visibility buffer (a 64-bit word per pixel: depth bits above,
// the impostor's place in the list below, kept by atomic min), except those larger on screen than
// its limit or crossing the near plane, which it lists for the hardware path (the impostor draw reads
// that list, ImpostorDraw's `split`); those too large for one thread to walk get a workgroup each in a
// second, indirect dispatch. Inside the colour pass a resolve over the covered screen tiles
// (render/visibility_resolve.h) shades the covered pixels with the hardware path's shading and writes
// their depth, so the depth test merges them with the hardware-drawn meshes and impostors. Impostors
// a few pixels across are averaged into the far layer instead (render/far_crowd_layer.h) while far-crowd
// is on. Shadows stay on the hardware path.
#include <cstdint>
#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include <glm/glm.hpp>

#include "gpu/buffer.h"
#include "gpu/descriptor_bundle.h"
#include "render/crowd_buffers.h"
#include "render/draw_lists.h"
#include "render/far_crowd_layer.h"
#include "render/geometry_pool.h"
#include "render/far_crowd_layer.h"
#include "render/impostor_atlas.h"
#include "render/target_format.h"
#include "render/visibility_resolve.h"

namespace gpu { class VulkanContext; }

namespace render {

class ImpostorRaster {
public:
    // `limitPixels`: the longest side of an impostor's screen rectangle the compute path draws
    // (infinity: every impostor not crossing the near plane). A multisampled target gets each covered
    // pixel in all its samples (render/raster_mode.h).
    // `resolveTilePixels`: the resolve's tile side (VisibilityResolve; 0: every pixel of the viewport).
    // `far`: which impostors the far layer takes while far-crowd is on (render/far_crowd_layer.h).
    ImpostorRaster(const gpu::VulkanContext& context, const GeometryPool& pool, const CrowdBuffers& crowd,
                   const DrawLists& lists, const ImpostorAtlas& atlas, VkDescriptorSetLayout sceneSetLayout,
                   const TargetFormat& target, std::uint32_t framesInFlight, float limitPixels,
                   std::uint32_t resolveTilePixels = kResolveTilePixels, FarCrowdSizes far = {});
    ~ImpostorRaster();
    ImpostorRaster(const ImpostorRaster&) = delete;
    ImpostorRaster& operator=(const ImpostorRaster&) = delete;

    // Outside any render pass, after culling and before ImpostorDraw::recordDraws: clears the slot's
    // visibility buffer (made to the viewport's extent, grown when it grows: the host has waited for
    // the slot's previous frame), rasterizes and lists the covered tiles for the resolve.
    // `blend`: the four atlas cells' blend, or the nearest cell (impostor-blend), as the colour draw.
    // `averageFar`: impostors up to farPixels go to the far layer (far-crowd; the layer is made the
    // first time).
    void record(VkCommandBuffer cmd, std::uint32_t slot, const glm::mat4& viewProjection, const glm::vec3& eye,
                VkExtent2D extent, bool blend, bool averageFar);
    // Inside the colour pass, after the hardware draws, its viewport set to `viewport` (the extent record had).
    void recordResolve(VkCommandBuffer cmd, std::uint32_t slot, VkDescriptorSet sceneSet, const glm::vec3& eye,
                       const VkRect2D& viewport, bool blend) const;
    // Inside the colour pass, after every opaque draw and resolve: the far layer blended over them (if
    // the slot's record averaged).
    void recordFarResolve(VkCommandBuffer cmd, std::uint32_t slot, VkDescriptorSet sceneSet, const glm::vec3& eye,
                          const VkRect2D& viewport) const;

    // ImpostorSplit, then the list of characters left to the hardware path (the colour draw's).
    const gpu::Buffer& split() const { return split_; }
    const gpu::Buffer& hardwareList() const { return hardwareList_; }
    // The slot's visibility buffer (tests) and its extent.
    const gpu::Buffer& visibility(std::uint32_t slot) const { return slots_[slot].visibility; }
    VkExtent2D visibilityExtent(std::uint32_t slot) const { return slots_[slot].extent; }
    // The slot's covered tiles (null when the resolve covers the viewport).
    const VisibilityTiles* tiles() const { return resolve_->tiles(); }
    // The far layer (tests), null until far-crowd was first on.
    const FarCrowdLayer* farLayer() const { return farLayer_.get(); }
    std::uint64_t bytes() const;

private:
    struct Slot {
        gpu::Buffer visibility;
        VkExtent2D extent{0, 0};
        std::unique_ptr<gpu::DescriptorBundle> rasterSet, resolveSet;
        bool farBound = false;  // the raster set binds the far layer's buffers
        bool averaged = false;  // the last record averaged into the far layer
    };
    void makeVisibility(std::uint32_t slot, VkExtent2D extent);
    void makeSets(std::uint32_t slot);  // the slot's raster and resolve sets over its buffers
    void release();

    const gpu::VulkanContext& context_;
    const CrowdBuffers& crowd_;
    const DrawLists& lists_;
    const ImpostorAtlas& atlas_;
    VkDescriptorSetLayout sceneSetLayout_;
    TargetFormat target_;
    std::uint32_t resolveTilePixels_;
    float limitPixels_;
    FarCrowdSizes far_;
    gpu::Buffer split_, hardwareList_;
    gpu::Buffer largeList_;  // the second dispatch's impostors (places in the impostor list)
    std::vector<Slot> slots_;
    std::unique_ptr<gpu::DescriptorBundle> drawSet_;  // what the resolve reads besides the visibility
    // Sets of the slots' layouts, kept for the pipeline layouts: a slot's sets are made again (identical
    // layouts) when its visibility buffer grows.
    std::unique_ptr<gpu::DescriptorBundle> rasterPrototype_, resolvePrototype_;
    VkPipelineLayout rasterLayout_ = VK_NULL_HANDLE;
    VkPipeline rasterPipeline_ = VK_NULL_HANDLE;
    VkPipeline largePipeline_ = VK_NULL_HANDLE;  // the same shader's second dispatch (the large impostors)
    VkPipeline splatPipeline_ = VK_NULL_HANDLE;  // its third (the far layer's splats)
    VkPipelineLayout resolveLayout_ = VK_NULL_HANDLE;
    std::unique_ptr<VisibilityResolve> resolve_;
    std::unique_ptr<FarCrowdLayer> farLayer_;
};

}  // namespace render
