#pragma once
// The shadow map's mesh casters rasterized in compute instead of by the graphics pipeline (issue 18,
// "the raster wall": on the H100 the hardware rasterizer is a small graphics slice, compute is every
// SM). A depth-only map needs no more than a 32-bit atomic min per texel: the casters' triangles go to
// a buffer of depth bits (shaders/shadow_raster.comp.glsl), packed to the map's 16-bit texels
// (shaders/shadow_pack.comp.glsl) and copied into the shadow map's depth image. The impostor casters
// go into the same depth buffer before the pack (render/impostor_shadow_raster.h), or, with that pass
// switched off, are drawn over the copied map by the graphics pipeline. The map is the hardware pass's
// texel for texel but for rounding on triangle edges (tests/test_shadow_raster.cpp).
// Only for methods whose skinned vertices are in a buffer (not the `vs` baseline, which skins while
// it draws), only when that buffer's position stream fits one storage binding, and only for maps whose
// float depths fit one (fits: a 4096² map takes 64 MiB, a 6000² one more than the 128 MiB every Vulkan
// device allows); otherwise the hardware pass draws the casters.
#include <cstdint>
#include <memory>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "gpu/buffer.h"
#include "gpu/descriptor_bundle.h"
#include "render/shadow_cascades.h"

namespace gpu { class VulkanContext; }

namespace render {

class DrawLists;
class GeometryPool;

// How the shadow map's mesh casters are drawn: the graphics pipeline's rasterizer, or this compute pass
// (where the method's skinned vertices allow it; else the hardware pass draws them).
enum class ShadowRasterPath { Hardware, Compute };

class ShadowMap;
struct SkinnedVertices;

// The light as the compute rasterizers take it: the first cascade's transform (rows x, y and depth:
// clip = row . (p, 1)) and each cascade's texels from the first's clip x, y (xy scale, zw offset; the
// cascades share the light's view and depth and differ in extents only).
struct ShadowRasterLight {
    glm::vec4 light[3];
    glm::vec4 toTexels[kMostShadowCascades];
};
ShadowRasterLight shadowRasterLight(const ShadowCascades& cascades, std::uint32_t mapSize);

class ShadowRaster {
public:
    ShadowRaster(const gpu::VulkanContext& context, const GeometryPool& pool, const DrawLists& lists,
                 const ShadowMap& map);
    ~ShadowRaster();
    ShadowRaster(const ShadowRaster&) = delete;
    ShadowRaster& operator=(const ShadowRaster&) = delete;

    // Whether these skinned vertices can be read as one storage binding on this device.
    bool canRead(const SkinnedVertices& vertices) const;
    // Outside any rendering pass, after the frame's skinning and lists: clears the depth buffer and
    // rasterizes the shadow pass's mesh casters into it, each into the squares of the cascades it
    // reaches (render/shadow_cascades.h). Rebinds the vertices when their buffer changed (a method
    // switch, made with the device idle). Other casters may be added (render/impostor_shadow_raster.h),
    // then pack.
    void rasterize(VkCommandBuffer cmd, const SkinnedVertices& vertices, const ShadowCascades& cascades);
    // After rasterize (and any other casters): the depths as the map's texels, for mapTexels.
    void pack(VkCommandBuffer cmd);
    // The float depths' buffer (one word a texel, row-major), for other casters' atomic mins.
    VkBuffer depthBits() const { return depth_.buffer; }
    // The skinned vertices' buffer is going away (a method switch): bind the next one afresh.
    void forgetVertices() { boundVertices_ = VK_NULL_HANDLE; }
    // The rasterized depth in the map's texel format (kShadowFormat, row-major), ready for
    // ShadowMap::copyFrom after rasterize.
    VkBuffer mapTexels() const { return packed_.buffer; }
    // The large triangles' records listed by the last rasterize (shadow_raster.comp.glsl): a uint count
    // and 12 bytes of padding, then a uvec4 a record of blocks. Read by tests, which check that path ran.
    const gpu::Buffer& largeTriangleRecords() const { return records_; }
    VkDeviceSize bytes() const { return depth_.size + packed_.size + records_.size; }
    // Device bytes for a map `size` texels a side: the float depths, the packed texels and the list
    // of large triangles' blocks.
    static std::uint64_t bytesFor(std::uint32_t size);
    // Whether this pass's buffers for a map `size` texels a side each fit one storage binding on a device
    // with these limits (the float depths, 4 bytes a texel, are the largest).
    static bool fits(const VkPhysicalDeviceLimits& limits, std::uint32_t size);

private:
    void bindVertices(const SkinnedVertices& vertices);
    void release();

    const gpu::VulkanContext& context_;
    const GeometryPool& pool_;
    const DrawLists& lists_;
    std::uint32_t size_ = 0;
    gpu::Buffer depth_;   // one float's bits a texel: the atomic min's target
    gpu::Buffer packed_;  // the same depths as the map's 16-bit texels, two a word: the copy's source
    gpu::Buffer records_;  // the large triangles' records, for the second dispatch (shadow_raster.comp.glsl)
    VkBuffer boundVertices_ = VK_NULL_HANDLE;
    std::unique_ptr<gpu::DescriptorBundle> rasterSet_;
    VkPipelineLayout rasterLayout_ = VK_NULL_HANDLE;
    VkPipeline rasterPipeline_ = VK_NULL_HANDLE;  // a workgroup a caster draw
    VkPipeline recordPipeline_ = VK_NULL_HANDLE;  // a workgroup a large triangle's record of blocks
    std::unique_ptr<gpu::DescriptorBundle> packSet_;
    VkPipelineLayout packLayout_ = VK_NULL_HANDLE;
    VkPipeline packPipeline_ = VK_NULL_HANDLE;
};

}  // namespace render
