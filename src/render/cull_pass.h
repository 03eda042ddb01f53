#pragma once
// Culling and level of detail for a frame, on the GPU (or, for reference, on the CPU), then the prefix
// sums and the indirect commands that the skinning and draw passes consume (render/draw_lists.h).
// Three compute dispatches: cull (one thread per character), finalize (one thread: bucket bases),
// emit (one thread per visible character: its draw command). With a mesh-level cap, three more between
// cull and finalize decide which candidates keep their meshes, farthest demoted first
// (shaders/mesh_cut.glsl.inc): cutoff (one workgroup), split (one thread per candidate), resolve (one
// workgroup).
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "gpu/buffer.h"
#include "gpu/descriptor_bundle.h"
#include "gpu_types.h"
#include "render/crowd_buffers.h"
#include "render/draw_lists.h"
#include "render/geometry_pool.h"
#include "render/shadow_cascades.h"

namespace gpu { class VulkanContext; }

namespace render {

enum class CullMode { Gpu, Cpu, Off };
const char* cullModeName(CullMode mode);
// "gpu", "cpu", "off"; false for anything else.
bool parseCullMode(const std::string& name, CullMode& mode);

struct CullSettings {
    CullMode mode = CullMode::Gpu;
    bool lod = true;
    // A character is drawn at LOD 0 while its pose sphere's projected diameter is at least
    // lodThresholds[0] pixels, at LOD 1 while at least lodThresholds[1], else at LOD 2.
    float lodThresholds[2] = {150.0f, 50.0f};
    // A character keeps its level until its size passes a threshold by this fraction of it.
    float hysteresis = 0.1f;
    // Fades (docs/picture-quality.md, "No pops"): within that fraction of a threshold, the coarser
    // level's share rises linearly across the band instead of the level being kept by hysteresis: a
    // character fading between mesh levels is skinned at the finer one and morphed toward the coarser
    // (shaders/lod_morph.glsl.inc), one fading into its impostor is drawn at both with complementary
    // screen-space dither masks. Only with the methods that skin into a buffer every frame: the
    // recorder turns it off for the vertex-shader methods and the static ceiling.
    bool lodFade = true;
    // The impostor level (with LOD on): below impostorThreshold pixels a character is drawn as an
    // impostor (render/impostor_atlas.h). Must be below lodThresholds[1].
    bool impostors = false;
    float impostorThreshold = 32.0f;
    // Shadow LOD (with shadows on; docs/gpu-driven-frame.md, "Shadow LOD"): a caster is drawn into the
    // shadow map at LOD 0 while its pose sphere's diameter covers at least shadowLodThresholds[0]
    // texels of the map, at LOD 1 while at least shadowLodThresholds[1], else at LOD 2, and never finer
    // than in view; under shadowMinTexels it is not drawn into the map. Off: casters at their view level.
    bool shadowLod = true;
    float shadowLodThresholds[2] = {150.0f, 50.0f};
    float shadowMinTexels = 2.0f;
};

// The cull pass's uniforms for a camera: frustum planes from the view-projection, the eye, and the
// pixel scale of a `viewportHeight`-pixel image with this vertical field of view.
gpu::CullUniforms makeCullUniforms(const CullSettings& settings, const glm::mat4& viewProjection, const glm::vec3& eye,
                                   float verticalFov, std::uint32_t viewportHeight, std::uint32_t characters,
                                   std::uint32_t buckets, std::uint32_t maxGroups);

// The shadow map's part of the uniforms: whether casters are kept (shadows on), each cascade's volume
// (its orthographic view-projection) as planes and its texels per world unit (a map of `mapSize` texels
// a side), the shadow LOD's thresholds and the light's direction.
void setShadowUniforms(gpu::CullUniforms& uniforms, const CullSettings& settings, bool shadows,
                       const ShadowCascades& cascades, std::uint32_t mapSize, const glm::vec3& towardsLight);

class CullPass {
public:
    CullPass(const gpu::VulkanContext& context, const GeometryPool& pool, const CrowdBuffers& crowd, DrawLists& lists,
             std::uint32_t framesInFlight);
    ~CullPass();
    CullPass(const CullPass&) = delete;
    CullPass& operator=(const CullPass&) = delete;

    // Records culling for the frame in `frameSlot`: the lists, bases and commands are ready for every
    // later stage (indirect reads, vertex, fragment and compute shaders) when it returns.
    // `fixedLayout`: draws read every character's own skinned slot (the static method).
    // `characterDraws`: also write one draw per character slot (the vertex-shader baseline).
    void record(VkCommandBuffer cmd, std::uint32_t frameSlot, const gpu::CullUniforms& uniforms, CullMode mode,
                bool fixedLayout, bool characterDraws);

    // The per-character draws were made or dropped (DrawLists::setCharacterDraws): bind the new buffer.
    void rebindCharacterDraws();

    // The lodState of the CPU path (one per character: last level + 1, or 0).
    const std::vector<std::uint32_t>& cpuLodState() const { return cpuLodState_; }

private:
    void recordCpuCulling(VkCommandBuffer cmd, std::uint32_t frameSlot, const gpu::CullUniforms& uniforms);
    void recordMeshCut(VkCommandBuffer cmd);
    VkPipeline createPipeline(std::span<const std::uint32_t> spirv);
    void release();

    const gpu::VulkanContext& context_;
    const GeometryPool& pool_;
    const CrowdBuffers& crowd_;
    DrawLists& lists_;
    VkDeviceSize uniformStride_;
    gpu::Buffer uniforms_;
    std::unique_ptr<gpu::DescriptorBundle> descriptors_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline cull_ = VK_NULL_HANDLE, finalize_ = VK_NULL_HANDLE, emit_ = VK_NULL_HANDLE;
    VkPipeline cutoff_ = VK_NULL_HANDLE, split_ = VK_NULL_HANDLE, resolve_ = VK_NULL_HANDLE;  // the mesh cut
    std::vector<std::uint32_t> cpuLodState_;
};

}  // namespace render
