#pragma once
// Vulkan failures as exceptions that say which call failed, where, and what the user can do.
#include <stdexcept>
#include <string>

#include <vulkan/vulkan.h>

#include "gpu/error.h"

namespace gpu {

const char* resultName(VkResult result);

// Throws Error naming the call, the source location and a hint for the common failures.
[[noreturn]] void throwVulkanError(VkResult result, const char* call, const char* file, int line);

}  // namespace gpu

#define VK_CHECK(call)                                                                   \
    do {                                                                                 \
        const VkResult vkCheckResult_ = (call);                                          \
        if (vkCheckResult_ < 0) ::gpu::throwVulkanError(vkCheckResult_, #call, __FILE__, __LINE__); \
    } while (0)
