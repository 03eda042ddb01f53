#pragma once
// Setup commands outside the frame loop (uploads, clears, the impostor bake). On a device the program
// owns they are recorded into a temporary command buffer, submitted and waited for; on a borrowed
// device they wait in the context's SetupQueue for the host to record and submit them.
#include <functional>

#include <vulkan/vulkan.h>

namespace gpu {

class VulkanContext;

// The submission ends with a full memory barrier to the host, so anything it wrote is visible to
// later submissions and to mapped reads once this returns. `release` frees what the commands read
// (staging buffers) once they have run: at once when submitted here, later when deferred. A deferred
// `record` runs after this returns: it must capture by value what it needs.
void runOneShot(const VulkanContext& context, std::function<void(VkCommandBuffer)> record,
                std::function<void()> release = {});

// Submits and waits even on a borrowed device: for the programs' own readbacks, never the library's.
void runOneShotNow(const VulkanContext& context, const std::function<void(VkCommandBuffer)>& record);

}  // namespace gpu
