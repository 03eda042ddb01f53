#pragma once
// The far crowd's layer (docs/picture-quality.md, "The far crowd averaged"). Impostors a few pixels
// across do not win whole pixels of the visibility buffer: the compute rasterizer adds their
// coverage-weighted surface (albedo, normal, radius, coverage: FAR_CROWD_* in shaders/gpu_types.h) to
// this layer's per-pixel sums and keeps the nearest contribution's depth in a visibility word of its
// own. Inside the colour pass, last, a resolve over the layer's covered tiles lights each pixel's
// averaged surface and blends it over what is behind by its coverage, depth-tested against the meshes
// and opaque impostors. Made by the impostor rasterizer (render/impostor_raster.h) when far-crowd is
// first on; each frame in flight has its own buffers, made to the viewport's extent.
#include <cstdint>
#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include <glm/glm.hpp>

#include "gpu/buffer.h"
#include "gpu/descriptor_bundle.h"
#include "render/target_format.h"
#include "render/visibility_resolve.h"

namespace gpu { class VulkanContext; }

namespace render {

// The largest impostor (its screen rectangle's longer side, pixels) that is averaged into the layer;
// docs/choices.md gives the measurement behind it.
constexpr float kFarCrowdPixels = 16.0f;
// The largest impostor (pixels across) whose pixels are spread from its quadrants' mean texels
// instead of n x n sub-samples a pixel (far_crowd.glsl.inc, splatPixels); 0: none (tests, to compare
// with the sub-samples). Under two pixels the sub-samples cost the most: docs/picture-quality.md.
constexpr float kFarCrowdSplatPixels = 2.0f;

// Which impostors the far layer takes, by their screen rectangle's longer side in pixels.
struct FarCrowdSizes {
    float averaged = kFarCrowdPixels;       // at most this: averaged into the layer
    float splatted = kFarCrowdSplatPixels;  // under this: from the quadrants' means
};

class FarCrowdLayer {
public:
    FarCrowdLayer(const gpu::VulkanContext& context, VkDescriptorSetLayout sceneSetLayout, const TargetFormat& target,
                  std::uint32_t framesInFlight, std::uint32_t resolveTilePixels);
    ~FarCrowdLayer();
    FarCrowdLayer(const FarCrowdLayer&) = delete;
    FarCrowdLayer& operator=(const FarCrowdLayer&) = delete;

    // Whether the layer's buffers for `extent` fit one storage binding each on a device with these limits
    // (the sums, 32 bytes a pixel, are the largest: 2048 x 2048 pixels in the 128 MiB every device allows).
    static bool fits(const VkPhysicalDeviceLimits& limits, VkExtent2D extent);
    // The slot's buffers at `extent` (made again when it changes: the host has waited for the slot's
    // previous frame; the rasterizer's set then binds the new ones).
    void fit(std::uint32_t slot, VkExtent2D extent);
    // Outside any render pass, before the rasterizer writes: empties the slot's layer (the previous
    // frame's reads of it are waited for by the caller's barrier).
    void recordClear(VkCommandBuffer cmd, std::uint32_t slot) const;
    // After the rasterizer's last write (made visible to compute reads): lists the covered tiles.
    void recordTiles(VkCommandBuffer cmd, std::uint32_t slot);
    // Inside the colour pass, after every opaque draw and resolve, its viewport set to `viewport`.
    void recordResolve(VkCommandBuffer cmd, std::uint32_t slot, VkDescriptorSet sceneSet, const glm::vec3& eye,
                       const VkRect2D& viewport) const;

    const gpu::Buffer& depth(std::uint32_t slot) const { return slots_[slot].depth; }
    const gpu::Buffer& sums(std::uint32_t slot) const { return slots_[slot].sums; }
    const VisibilityTiles* tiles() const { return resolve_->tiles(); }
    std::uint64_t bytes() const;

private:
    struct Slot {
        gpu::Buffer depth, sums;
        VkExtent2D extent{0, 0};
        std::unique_ptr<gpu::DescriptorBundle> resolveSet;
    };
    void release();

    const gpu::VulkanContext& context_;
    std::vector<Slot> slots_;
    std::unique_ptr<gpu::DescriptorBundle> prototype_;  // the slots' set layout, for the pipeline layout
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    std::unique_ptr<VisibilityResolve> resolve_;
};

}  // namespace render
