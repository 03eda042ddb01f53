#pragma once
// Small characters' meshes in the compute rasterizer (docs/compute-raster.md, "Meshes"). After skinning,
// a split pass takes from the colour pass's compacted draw list each character whose pose sphere is
// smaller on screen than the limit and wholly in front of the eye, lists it and leaves its colour
// command with no instance; a raster pass draws the listed characters' skinned triangles into a
// visibility buffer (a 64-bit word per pixel: depth bits above, the list place and triangle below,
// kept by atomic min), with the hardware's rules (pixel centres, 1/256-pixel snapping, the top-left
// rule, back faces culled). Inside the colour pass a resolve over the covered screen tiles
// (render/visibility_resolve.h) interpolates and shades the covered pixels as the draw pass does and
// writes their depth, so the depth test merges them with everything else. It reads the skinned vertices as storage: the methods that skin into a buffer.
#include <cstdint>
#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include <glm/glm.hpp>

#include "gpu/buffer.h"
#include "gpu/descriptor_bundle.h"
#include "render/character_draw.h"
#include "render/crowd_buffers.h"
#include "render/draw_lists.h"
#include "render/geometry_pool.h"
#include "render/target_format.h"
#include "render/visibility_resolve.h"

namespace gpu { class VulkanContext; }

namespace render {

// Bits of an id that number the triangles of a model's largest level (at least 1), and the most
// characters a frame's list holds for a draw list of `drawCapacity` (the rest stay on the hardware).
std::uint32_t meshRasterTriangleBits(std::uint32_t largestTriangleCount);
std::uint32_t meshRasterListCapacity(std::uint32_t drawCapacity, std::uint32_t triangleBits);
// Device bytes of the split and list (the visibility buffers, 8 bytes a pixel and frame in flight, follow
// the viewport).
std::uint64_t meshRasterListBytes(std::uint32_t listCapacity);

class MeshRaster {
public:
    // `limitPixels`: the largest pose sphere (diameter on screen) the compute path draws (infinity:
    // every character wholly in front of the eye). A multisampled target gets each covered pixel in all
    // its samples (render/raster_mode.h).
    // `resolveTilePixels`: the resolve's tile side (VisibilityResolve; 0: every pixel of the viewport).
    MeshRaster(const gpu::VulkanContext& context, const GeometryPool& pool, const CrowdBuffers& crowd,
               const DrawLists& lists, VkDescriptorSetLayout sceneSetLayout, const TargetFormat& target,
               std::uint32_t framesInFlight, float limitPixels, std::uint32_t resolveTilePixels = kResolveTilePixels);
    ~MeshRaster();
    MeshRaster(const MeshRaster&) = delete;
    MeshRaster& operator=(const MeshRaster&) = delete;

    // Whether the pass can read these skinned vertices (a buffer whose position stream a storage
    // binding can hold).
    bool canRead(const SkinnedVertices& vertices) const;
    // Outside any render pass, after skinning: clears the slot's visibility buffer (made to the
    // viewport's extent), splits the colour list, rasterizes and lists the covered tiles for the resolve. `pixelsPerUnit`: the viewport's height
    // over 2 tan(fovY / 2), as culling's projected size.
    void record(VkCommandBuffer cmd, std::uint32_t slot, const SkinnedVertices& vertices,
                const glm::mat4& viewProjection, const glm::vec3& eye, float pixelsPerUnit, VkExtent2D extent);
    // Inside the colour pass, its viewport set to `viewport` (the extent record had).
    void recordResolve(VkCommandBuffer cmd, std::uint32_t slot, VkDescriptorSet sceneSet, const glm::vec3& eye,
                       const VkRect2D& viewport) const;
    // Forget the bound vertices (a method switch may reuse the buffer's handle).
    void forgetVertices();

    // MeshSplit; the listed draws (places in the colour list); the slot's visibility buffer (tests).
    const gpu::Buffer& split() const { return split_; }
    const gpu::Buffer& list() const { return list_; }
    const gpu::Buffer& visibility(std::uint32_t slot) const { return slots_[slot].visibility; }
    VkExtent2D visibilityExtent(std::uint32_t slot) const { return slots_[slot].extent; }
    // The slot's covered tiles (null when the resolve covers the viewport).
    const VisibilityTiles* tiles() const { return resolve_->tiles(); }
    // Bits of an id that hold the triangle (enough for the largest model's), and the most characters
    // an id can name.
    std::uint32_t triangleBits() const { return triangleBits_; }
    std::uint32_t listCapacity() const { return listCapacity_; }
    std::uint64_t bytes() const;

private:
    struct Slot {
        gpu::Buffer visibility;
        VkExtent2D extent{0, 0};
        VkBuffer vertices = VK_NULL_HANDLE;  // what the sets below bind
        std::unique_ptr<gpu::DescriptorBundle> rasterSet, resolveSet;
    };
    void makeSets(std::uint32_t slot, VkExtent2D extent, const SkinnedVertices& vertices);
    void makePipelines(VkDescriptorSetLayout sceneSetLayout, std::uint32_t framesInFlight, std::uint32_t resolveTilePixels);
    void release();

    const gpu::VulkanContext& context_;
    const GeometryPool& pool_;
    const CrowdBuffers& crowd_;
    const DrawLists& lists_;
    TargetFormat target_;
    float limitPixels_;
    std::uint32_t triangleBits_ = 1;
    std::uint32_t listCapacity_ = 0;
    gpu::Buffer split_, list_;
    std::vector<Slot> slots_;
    std::unique_ptr<gpu::DescriptorBundle> splitSet_;
    VkDescriptorSetLayout sceneSetLayout_ = VK_NULL_HANDLE;
    VkPipelineLayout splitLayout_ = VK_NULL_HANDLE, rasterLayout_ = VK_NULL_HANDLE, resolveLayout_ = VK_NULL_HANDLE;
    VkPipeline splitPipeline_ = VK_NULL_HANDLE, rasterPipeline_ = VK_NULL_HANDLE;
    std::unique_ptr<VisibilityResolve> resolve_;
};

}  // namespace render
