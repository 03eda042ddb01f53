#include "skin/storage_ranges.h"

#include <algorithm>
#include <limits>
#include <optional>

#include "gpu/buffer.h"
#include "gpu/vulkan_error.h"
#include "render/crowd_buffers.h"
#include "skin/skinned_capacity.h"
#include "skin/skinned_vertex_buffer.h"

namespace skin {
namespace {

// Characters of this mix whose share of the binding fits `range` (the average share: errs low).
std::uint64_t charactersFitting(const StorageBinding& binding, std::uint64_t range) {
    const double perCharacter = static_cast<double>(binding.bytes) / static_cast<double>(std::max<std::uint64_t>(binding.holds, 1));
    const auto fitting = static_cast<std::uint64_t>(static_cast<double>(range) / std::max(perCharacter, 1.0));
    // Past its cap it holds no more, so a cap that fits lets any crowd fit.
    return binding.capacityCap > 0 && fitting >= binding.capacityCap ? std::numeric_limits<std::uint64_t>::max() : fitting;
}

bool storesSkinnedVertices(Method method) {
    return method == Method::Compute || method == Method::Static || method == Method::TwoPassDirect;
}

}  // namespace

std::vector<StorageBinding> storageBindings(const VkPhysicalDeviceLimits& limits, const crowd::Crowd& crowd,
                                            Method method, std::uint32_t meshCapacity, render::AnimationPath animation) {
    const std::uint64_t n = crowd.size();
    // Blocks per mesh slot stop growing at the mesh capacity, as the skinned vertices do.
    const bool perSlot = boneBlocksFor(method, animation) == render::BoneBlocks::PerMeshSlot;
    const std::uint32_t slots = meshCapacity > 0 && meshCapacity < n ? meshCapacity : static_cast<std::uint32_t>(n);
    const render::BoneLayout bones =
        render::planBones(limits, crowd, boneBlocksFor(method, animation), slots);
    std::vector<StorageBinding> bindings = {
        {"bone matrices", bones.bytes(), perSlot ? slots : n, perSlot ? meshCapacity : 0u},
        {"character records", n * sizeof(gpu::CharacterRecord), n, 0}};
    if (storesSkinnedVertices(method)) {
        const SkinnedCapacity capacity = skinnedCapacity(crowd, meshCapacity);
        const bool fixed = method == Method::Static;  // a slot per character and LOD, whatever the cap
        // Positions and normals are two bindings of the same size.
        bindings.push_back({"skinned vertex positions",
                            SkinnedVertexBuffer::bytesFor(fixed ? capacity.fixed : capacity.perFrame) / 2,
                            !fixed && capacity.meshCapacity > 0 ? capacity.meshCapacity : n, fixed ? 0u : meshCapacity});
    }
    return bindings;
}

std::optional<StorageRangeProblem> storageRangeProblem(const VkPhysicalDeviceLimits& limits, const crowd::Crowd& crowd,
                                                       Method method, std::uint32_t meshCapacity,
                                                       render::AnimationPath animation) {
    const std::uint64_t range = limits.maxStorageBufferRange;
    for (const StorageBinding& b : storageBindings(limits, crowd, method, meshCapacity, animation)) {
        if (b.bytes <= range) continue;
        const std::uint64_t fitting = charactersFitting(b, range);
        const bool capped = b.capacityCap > 0 && b.holds == b.capacityCap;
        const std::string advice = capped ? "a mesh capacity of at most " + std::to_string(fitting) + " fits"
                                          : "at most " + std::to_string(fitting) + " of these characters fit" +
                                                (b.capacityCap > 0 ? ", or a mesh capacity of that many" : "");
        return StorageRangeProblem{std::string(methodName(method)) + " binds " + gpu::formatBytes(b.bytes) + " of " +
                                       b.what + " as one storage buffer, over this device's limit of " +
                                       gpu::formatBytes(range) + " (" + advice + ")",
                                   capped};
    }
    return std::nullopt;
}

void checkStorageRanges(const VkPhysicalDeviceLimits& limits, const crowd::Crowd& crowd, Method method,
                        std::uint32_t meshCapacity, render::AnimationPath animation) {
    if (const auto problem = storageRangeProblem(limits, crowd, method, meshCapacity, animation))
        throw gpu::Error("a crowd of " + std::to_string(crowd.size()) + " characters: " + problem->message,
                         gpu::ErrorKind::Unsupported);
}

std::uint64_t maxCharactersInStorageRange(const VkPhysicalDeviceLimits& limits, const crowd::Crowd& crowd,
                                          Method method, std::uint32_t meshCapacity, render::AnimationPath animation) {
    std::uint64_t most = std::numeric_limits<std::uint64_t>::max();
    for (const StorageBinding& b : storageBindings(limits, crowd, method, meshCapacity, animation))
        most = std::min(most, charactersFitting(b, limits.maxStorageBufferRange));
    return most;
}

}  // namespace skin
