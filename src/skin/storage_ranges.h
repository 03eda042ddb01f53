#pragma once
// The buffers a crowd binds whole as one storage buffer, against the device's maxStorageBufferRange
// (128 MiB on lavapipe, 2 or 4 GiB on desktop GPUs): a binding past it is invalid Vulkan, so a crowd
// that needs one is refused before anything is allocated, and the viewer offers no such crowd.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "crowd/crowd.h"
#include "skin/skinning_method.h"

namespace skin {

struct StorageBinding {
    std::string what;
    std::uint64_t bytes = 0;
    std::uint64_t holds = 0;       // characters it is sized for: the crowd, or the mesh capacity in effect
    std::uint32_t capacityCap = 0;  // it stops growing past this many characters (--mesh-capacity; 0: never)
};

// What this crowd binds with this method and animation path: bone matrices (a block per mesh slot,
// or per character: skin::boneBlocksFor) and character records always; the skinned
// vertices' position (and, as large, normal) stream for the methods whose shaders store into them
// (compute, static, two-pass-direct; two-pass copies into them and vs reads no skinned vertices).
std::vector<StorageBinding> storageBindings(const VkPhysicalDeviceLimits& limits, const crowd::Crowd& crowd,
                                            Method method, std::uint32_t meshCapacity,
    render::AnimationPath animation = render::AnimationPath::Gpu);

// The first binding over the range, in one line: its size, the limit and how many characters of this
// crowd's mix (or what mesh capacity) would fit. `meshCapacityBound`: the binding is sized by the mesh
// capacity, not the crowd, so a smaller capacity is the way out.
struct StorageRangeProblem {
    std::string message;
    bool meshCapacityBound = false;
};
std::optional<StorageRangeProblem> storageRangeProblem(const VkPhysicalDeviceLimits& limits, const crowd::Crowd& crowd,
                                                       Method method, std::uint32_t meshCapacity,
    render::AnimationPath animation = render::AnimationPath::Gpu);
// Throws gpu::Error(Unsupported) with "a crowd of N characters: " and the problem's message.
void checkStorageRanges(const VkPhysicalDeviceLimits& limits, const crowd::Crowd& crowd, Method method,
                        std::uint32_t meshCapacity,
    render::AnimationPath animation = render::AnimationPath::Gpu);

// The most characters of this crowd's mix (same models, same shares) whose bindings all fit.
std::uint64_t maxCharactersInStorageRange(const VkPhysicalDeviceLimits& limits, const crowd::Crowd& crowd,
                                          Method method, std::uint32_t meshCapacity,
    render::AnimationPath animation = render::AnimationPath::Gpu);

}  // namespace skin
