#include "render/draw_lists.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "gpu/one_shot_commands.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"

namespace render {

std::uint32_t skinningCharactersPerGroup(const gpu::VulkanContext& context, std::uint32_t joints) {
    const std::uint32_t shared = context.properties.limits.maxComputeSharedMemorySize;
    const std::uint32_t perCharacter = joints * static_cast<std::uint32_t>(sizeof(gpu::BoneRows));
    if (perCharacter > shared)
        throw gpu::Error("compute: " + std::to_string(joints) + " joints do not fit in shared memory");
    return std::clamp<std::uint32_t>(std::min<std::uint32_t>(16384, shared) / std::max(perCharacter, 1u), 1, 8);
}

namespace {

// Buckets in model-major order (model x LOD_COUNT + lod), each listing up to all its model's characters.
// With a cap, a bucket never lists more than the cap, and a frame never skins more than the cap's
// characters at the largest LOD 0 of the crowd.
std::vector<gpu::BucketRecord> planBuckets(const gpu::VulkanContext& context, const GeometryPool& pool,
                                           const CrowdBuffers& crowd, std::uint32_t meshCapacity,
                                           std::uint64_t& skinnedCapacity, std::uint64_t& fixedCapacity) {
    std::vector<std::uint32_t> members(pool.modelCount(), 0);
    for (const gpu::CharacterRecord& c : crowd.records()) ++members[c.ids.x];
    std::vector<gpu::BucketRecord> buckets;
    std::uint32_t listBase = 0;
    std::uint32_t largestLod0 = 0;
    skinnedCapacity = fixedCapacity = 0;
    for (std::uint32_t m = 0; m < pool.modelCount(); ++m) {
        const gpu::ModelRecord& model = pool.models()[m];
        const std::uint32_t perGroup = skinningCharactersPerGroup(context, model.info.y);
        skinnedCapacity += static_cast<std::uint64_t>(members[m]) * model.lodVertexCount[0];
        largestLod0 = std::max(largestLod0, model.lodVertexCount[0]);
        const std::uint32_t listed = meshCapacity > 0 ? std::min(members[m], meshCapacity) : members[m];
        for (std::uint32_t l = 0; l < LOD_COUNT; ++l) {
            gpu::BucketRecord b{};
            b.list = glm::uvec4(m, l, listBase, listed);
            b.mesh = glm::uvec4(model.lodFirstIndex[l], model.lodIndexCount[l], model.lodVertexCount[l], model.info.x);
            b.fixedLayout = glm::uvec4(static_cast<std::uint32_t>(std::min<std::uint64_t>(fixedCapacity, UINT32_MAX)),
                                       perGroup, 0u, 0u);
            fixedCapacity += static_cast<std::uint64_t>(members[m]) * model.lodVertexCount[l];
            listBase += listed;
            buckets.push_back(b);
        }
    }
    if (meshCapacity > 0) skinnedCapacity = std::min<std::uint64_t>(skinnedCapacity, std::uint64_t{meshCapacity} * largestLod0);
    return buckets;
}

}  // namespace

std::uint64_t DrawLists::bytesFor(std::uint64_t characters, std::uint32_t buckets, std::uint32_t meshCapacity,
                                  bool characterDraws) {
    // Per character: the LOD state, the shadow state and two impostor list entries (in view, casting),
    // and for the vs baseline its two draw commands (colour, shadow; else one command in all); per
    // mesh-level character (all, without a cap): visible-list and shadow-list entries (one each per
    // LOD) and three draw commands (colour, shadow, fading into its impostor); with a cap, the cut's
    // histograms and per-character lists.
    const std::uint64_t meshLevel = meshCapacity > 0 ? std::min<std::uint64_t>(characters, meshCapacity) : characters;
    const std::uint64_t perCharacterDraws =
        characterDraws ? 2 * std::max<std::uint64_t>(characters, 1) : 1;
    return perCharacterDraws * sizeof(gpu::DrawIndexedCommand) + characters * (4 + 4 + 2 * 4) +
           meshLevel * (2 * LOD_COUNT * 4 + 3 * sizeof(gpu::DrawIndexedCommand)) + sizeof(gpu::ImpostorFrame) +
           buckets * (sizeof(gpu::BucketRecord) + sizeof(gpu::BucketFrame) + 2 * sizeof(gpu::DrawIndexedCommand) + 16) +
           meshCutSizes(characters, meshCapacity).total();
}

DrawLists::DrawLists(const gpu::VulkanContext& context, const GeometryPool& pool, const CrowdBuffers& crowd,
                     std::uint32_t framesInFlight, std::uint32_t meshCapacity, bool characterDraws)
    : context_(context),
      buckets_(planBuckets(context, pool, crowd, meshCapacity, skinnedCapacity_, fixedCapacity_)),
      characterCount_(crowd.characterCount()),
      meshCapacity_(meshCapacity),
      drawCapacity_(meshCapacity > 0 ? std::min(meshCapacity, characterCount_) : characterCount_) {
    const VkDeviceSize n = std::max(characterCount_, 1u);
    VkDeviceSize listed = 0;
    for (const gpu::BucketRecord& bucket : buckets_) listed += bucket.list.w;
    shadowListBase_ = static_cast<std::uint32_t>(listed);
    const VkDeviceSize b = buckets_.size();
    constexpr VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    constexpr VkBufferUsageFlags filled = storage | VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    // Transfer source too: tests and tools read the lists back.
    constexpr VkBufferUsageFlags indirect = storage | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    constexpr auto device = gpu::MemoryUse::DeviceLocal;
    try {
        bucketRecords_ = gpu::createBufferWithData(context, std::as_bytes(std::span(buckets_)), storage, "LOD buckets");
        bucketFrames_ = gpu::createBuffer(context, b * sizeof(gpu::BucketFrame),
                                          filled | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, device, "bucket counts");
        totals_ = gpu::createBuffer(context, sizeof(gpu::DrawTotals), indirect, device, "draw totals");
        // Each of these holds the colour pass's entries, then the shadow pass's.
        visible_ = gpu::createBuffer(context, std::max<VkDeviceSize>(2 * listed, 1) * 4, filled, device,
                                     "visible and shadow lists");
        draws_ = gpu::createBuffer(context, 3 * std::max(drawCapacity_, 1u) * sizeof(gpu::DrawIndexedCommand), indirect,
                                   device, "draw commands (colour, shadow, fading into impostors)");
        characterDraws_ = createCharacterDraws(characterDraws);
        characterDrawsOn_ = characterDraws;
        bucketDraws_ = gpu::createBuffer(context, 2 * b * sizeof(gpu::DrawIndexedCommand), indirect, device,
                                         "per-bucket draw commands");
        skinDispatches_ = gpu::createBuffer(context, b * sizeof(glm::uvec4), indirect, device, "skinning dispatches");
        lodState_ = gpu::createBuffer(context, n * 4, filled, device, "LOD state");
        impostorFrame_ = gpu::createBuffer(context, sizeof(gpu::ImpostorFrame), indirect | filled, device, "impostor draw");
        impostorList_ = gpu::createBuffer(context, 2 * n * 4, filled, device, "impostor lists (in view, casting)");
        shadowStates_ = gpu::createBuffer(context, n * 4, filled, device, "shadow states");
        const MeshCutSizes cut = meshCutSizes(characterCount_, meshCapacity_);
        meshCut_ = gpu::createBuffer(context, cut.cutBuffer(), filled | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, device,
                                     "mesh cut and size histograms");
        meshCandidates_ = gpu::createBuffer(context, cut.candidates, storage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, device,
                                            "mesh-level candidates");
        meshBoundary_ = gpu::createBuffer(context, cut.boundary, storage, device, "mesh cut's boundary");
        gpu::runOneShot(context, [state = lodState_.buffer](VkCommandBuffer cmd) {
            vkCmdFillBuffer(cmd, state, 0, VK_WHOLE_SIZE, 0);
        });
        for (std::uint32_t i = 0; i < framesInFlight; ++i) {
            // The bucket counts, then the impostor level's figures.
            readback_.push_back(gpu::createBuffer(context, b * sizeof(gpu::BucketFrame) + sizeof(gpu::ImpostorFrame),
                                                  VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                                  gpu::MemoryUse::HostReadback, "bucket counts (readback)"));
            std::memset(readback_.back().mapped, 0, readback_.back().size);
        }
        cpuStaging_.resize(framesInFlight);
    } catch (...) {
        release();
        throw;
    }
}

DrawLists::~DrawLists() { release(); }

gpu::Buffer DrawLists::createCharacterDraws(bool on) const {
    // 20 bytes a character twice, 400 MB at 10,000,000: only the vs baseline draws from them.
    const VkDeviceSize commands = on ? 2 * VkDeviceSize{std::max(characterCount_, 1u)} : 1;
    return gpu::createBuffer(context_, commands * sizeof(gpu::DrawIndexedCommand),
                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                                 VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                             gpu::MemoryUse::DeviceLocal, "per-character draw commands");
}

void DrawLists::setCharacterDraws(bool on) {
    if (on == characterDrawsOn_) return;
    gpu::Buffer draws = createCharacterDraws(on);  // first: if it cannot be had, nothing changes
    gpu::destroyBuffer(context_, characterDraws_);
    characterDraws_ = draws;
    characterDrawsOn_ = on;
}

void DrawLists::release() {
    for (gpu::Buffer& buffer : cpuStaging_) gpu::destroyBuffer(context_, buffer);
    for (gpu::Buffer& buffer : readback_) gpu::destroyBuffer(context_, buffer);
    for (gpu::Buffer* buffer : {&shadowStates_, &meshBoundary_, &meshCandidates_, &meshCut_, &impostorList_,
                                &impostorFrame_, &lodState_, &skinDispatches_, &bucketDraws_, &characterDraws_, &draws_,
                                &visible_, &totals_, &bucketFrames_, &bucketRecords_})
        gpu::destroyBuffer(context_, *buffer);
}

const gpu::Buffer& DrawLists::cpuStaging(std::uint32_t frameSlot) {
    // Made on first use: only the CPU path needs it (bucket counts, then the lists, then the shadow states).
    gpu::Buffer& staging = cpuStaging_[frameSlot];
    if (!staging.buffer)
        staging = gpu::createBuffer(context_, bucketFrames_.size + visible_.size + impostorFrame_.size + impostorList_.size +
                                                  shadowStates_.size,
                                    VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                    gpu::MemoryUse::HostUpload, "visible lists (CPU culling upload)");
    return staging;
}

LodCounts DrawLists::countsOf(std::uint32_t frameSlot) const {
    LodCounts counts;
    const auto* frames = static_cast<const gpu::BucketFrame*>(readback_[frameSlot].mapped);
    for (std::size_t b = 0; b < buckets_.size(); ++b) {
        const std::uint32_t lod = buckets_[b].list.y;
        counts.characters[lod] += frames[b].count;
        counts.triangles[lod] += static_cast<std::uint64_t>(frames[b].count) * (buckets_[b].mesh.y / 3);
        counts.skinnedVertices += static_cast<std::uint64_t>(frames[b].count) * buckets_[b].mesh.z;
        counts.shadowCharacters[lod] += frames[b].shadowCount;
        counts.shadowTriangles[lod] += static_cast<std::uint64_t>(frames[b].shadowCount) * (buckets_[b].mesh.y / 3);
    }
    gpu::ImpostorFrame impostors;
    std::memcpy(&impostors, frames + buckets_.size(), sizeof impostors);
    counts.impostors = impostors.count;
    counts.demoted = impostors.demoted;
    counts.shadowImpostors = impostors.shadowCount;
    return counts;
}

VkDeviceSize DrawLists::bytes() const {
    VkDeviceSize total = 0;
    for (const gpu::Buffer* buffer : {&shadowStates_, &meshBoundary_, &meshCandidates_, &meshCut_, &impostorList_, &impostorFrame_,
                                      &lodState_, &skinDispatches_, &bucketDraws_, &characterDraws_, &draws_, &visible_,
                                      &totals_, &bucketFrames_, &bucketRecords_})
        total += buffer->size;
    return total;
}

}  // namespace render
