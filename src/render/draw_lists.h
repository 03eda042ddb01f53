#pragma once
// What culling writes and every later pass reads, on the GPU: per (model, LOD) bucket the list of
// visible characters and their count; the bases that place each bucket's characters in the skinned
// vertex buffer and in the compacted draw list; the indirect draw and dispatch commands; each
// character's last level of detail (for hysteresis).
//
// Skinned vertices are dense: visible character k of bucket b has its vertices at
// frame[b].vertexBase + k x (vertices of b's LOD), so skinning work and memory traffic follow what
// is visible. The shadow pass has the same three kinds of command as the colour pass, after the colour
// ones in the same buffers: compacted draws of the casters (each its shadow level's indices over its
// skinned vertices), per-character draws and per-bucket instanced draws over each bucket's casters. The buffers that hold them are sized for the worst case (every character visible at
// LOD 0), since the CPU never learns this frame's counts.
#include <cstdint>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/buffer.h"
#include "gpu_types.h"
#include "render/crowd_buffers.h"
#include "render/geometry_pool.h"
#include "render/mesh_cut.h"

namespace gpu { class VulkanContext; }

namespace render {

// Characters a compute-skinning workgroup takes at once: their bones must fit the shared memory,
// kept under 16 KiB so several workgroups share a multiprocessor. Throws when one character's
// bones do not fit at all.
std::uint32_t skinningCharactersPerGroup(const gpu::VulkanContext& context, std::uint32_t joints);

// Visible characters and triangles of a finished frame, per level of detail.
struct LodCounts {
    std::uint32_t characters[LOD_COUNT] = {};
    std::uint64_t triangles[LOD_COUNT] = {};
    std::uint64_t skinnedVertices = 0;  // what a skinning pass skins: visible characters x their LOD's vertices
    std::uint32_t impostors = 0;  // characters drawn at the impostor level
    std::uint32_t demoted = 0;    // of those, sent there because the mesh levels were full (the cap)
    // The shadow pass: mesh casters and their triangles per shadow level, impostors casting a quad.
    std::uint32_t shadowCharacters[LOD_COUNT] = {};
    std::uint64_t shadowTriangles[LOD_COUNT] = {};
    std::uint32_t shadowImpostors = 0;
    std::uint32_t visible() const { return characters[0] + characters[1] + characters[2]; }
    std::uint64_t totalTriangles() const { return triangles[0] + triangles[1] + triangles[2]; }
    std::uint32_t shadowCasters() const { return shadowCharacters[0] + shadowCharacters[1] + shadowCharacters[2]; }
    std::uint64_t totalShadowTriangles() const { return shadowTriangles[0] + shadowTriangles[1] + shadowTriangles[2]; }
};

class DrawLists {
public:
    // `meshCapacity`: the most characters at a mesh level (LOD 0-2) in a frame, 0 for no cap. With a
    // cap, the skinned-vertex capacity, the draw list and each bucket's list are sized for it, not for
    // the whole crowd; culling demotes the smallest on screen beyond it to impostors (the cut's buffers,
    // render/mesh_cut.h).
    // `characterDraws`: the vs baseline's per-character draws are made (two per character); else the
    // buffer is one command long, until setCharacterDraws(true).
    DrawLists(const gpu::VulkanContext& context, const GeometryPool& pool, const CrowdBuffers& crowd,
              std::uint32_t framesInFlight, std::uint32_t meshCapacity = 0, bool characterDraws = true);
    ~DrawLists();
    DrawLists(const DrawLists&) = delete;
    DrawLists& operator=(const DrawLists&) = delete;

    // Device bytes these lists take for a crowd of this size and bucket count (checked before allocating).
    static std::uint64_t bytesFor(std::uint64_t characters, std::uint32_t buckets, std::uint32_t meshCapacity = 0,
                                  bool characterDraws = true);
    // Between frames, with the GPU idle: makes or drops the per-character draws (a new buffer, which
    // the cull pass binds again: CullPass::rebindCharacterDraws). Only the vs baseline reads them.
    void setCharacterDraws(bool on);
    bool hasCharacterDraws() const { return characterDrawsOn_; }

    std::uint32_t bucketCount() const { return static_cast<std::uint32_t>(buckets_.size()); }
    const std::vector<gpu::BucketRecord>& buckets() const { return buckets_; }
    // Skinned vertices when every character is visible at LOD 0: what a per-frame skinned buffer holds.
    std::uint64_t skinnedCapacity() const { return skinnedCapacity_; }
    // Skinned vertices of every character at every LOD, each in its own slot (the static method).
    std::uint64_t fixedCapacity() const { return fixedCapacity_; }

    const gpu::Buffer& bucketRecords() const { return bucketRecords_; }
    const gpu::Buffer& bucketFrames() const { return bucketFrames_; }
    const gpu::Buffer& totals() const { return totals_; }
    // Every bucket's visible list, then from shadowListBase() every bucket's list of shadow casters.
    const gpu::Buffer& visible() const { return visible_; }
    std::uint32_t shadowListBase() const { return shadowListBase_; }
    // The compacted draws: the colour pass's, then from drawCapacity() the shadow pass's, then from
    // fadingDrawBase() the colour draws of the characters fading into their impostors (their last
    // mesh level, dithered; they have no instance in the colour pass's).
    const gpu::Buffer& draws() const { return draws_; }
    // One per character slot: the colour pass's, then from characterCount() the shadow pass's (vs only:
    // one unused command otherwise).
    const gpu::Buffer& characterDraws() const { return characterDraws_; }
    // One per bucket: the colour pass's, then from bucketCount() the shadow pass's.
    const gpu::Buffer& bucketDraws() const { return bucketDraws_; }
    // Per character: its shadow this frame (gpu_types.h, SHADOW_*), written by culling.
    const gpu::Buffer& shadowStates() const { return shadowStates_; }
    const gpu::Buffer& skinDispatches() const { return skinDispatches_; }
    const gpu::Buffer& lodState() const { return lodState_; }
    // The impostor level: its counts (gpu::ImpostorFrame), and its list of characters in view, then
    // from characterCount() its list of characters that cast a shadow.
    const gpu::Buffer& impostorFrame() const { return impostorFrame_; }
    const gpu::Buffer& impostorList() const { return impostorList_; }
    // The mesh-level cap's cut (render/mesh_cut.h): the cut with its histograms and tie bits, the
    // candidates, the members of the cut's coarse bucket.
    const gpu::Buffer& meshCut() const { return meshCut_; }
    const gpu::Buffer& meshCandidates() const { return meshCandidates_; }
    const gpu::Buffer& meshBoundary() const { return meshBoundary_; }
    // The most mesh-level characters a frame draws: the draw list's length.
    std::uint32_t drawCapacity() const { return drawCapacity_; }
    // Where the draws of the characters fading into impostors start in draws() (after the shadow
    // pass's; as many at most).
    std::uint32_t fadingDrawBase() const { return 2 * drawCapacity_; }
    std::uint32_t meshCapacity() const { return meshCapacity_; }
    const gpu::Buffer& readback(std::uint32_t frameSlot) const { return readback_[frameSlot]; }
    // Where the CPU path writes a frame's counts and lists before they are copied to the GPU.
    const gpu::Buffer& cpuStaging(std::uint32_t frameSlot);
    std::uint32_t characterCount() const { return characterCount_; }

    // The counts of the frame whose readback copy landed in this slot (after its fence).
    LodCounts countsOf(std::uint32_t frameSlot) const;
    VkDeviceSize bytes() const;

private:
    void release();

    const gpu::VulkanContext& context_;
    std::vector<gpu::BucketRecord> buckets_;
    std::uint32_t characterCount_;
    std::uint32_t meshCapacity_, drawCapacity_;
    std::uint64_t skinnedCapacity_, fixedCapacity_;  // set by planBuckets, before this line runs
    std::uint32_t shadowListBase_ = 0;
    bool characterDrawsOn_ = false;
    gpu::Buffer createCharacterDraws(bool on) const;
    gpu::Buffer bucketRecords_, bucketFrames_, totals_, visible_, draws_, characterDraws_, bucketDraws_,
        skinDispatches_, lodState_, impostorFrame_, impostorList_, meshCut_, meshCandidates_, meshBoundary_,
        shadowStates_;
    std::vector<gpu::Buffer> readback_;
    std::vector<gpu::Buffer> cpuStaging_;
};

}  // namespace render
