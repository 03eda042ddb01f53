#pragma once
// Called by the recording code each time a pass ends, outside any rendering pass: where a profiler
// writes a timestamp or a debugger a label. Empty: nothing is called.
#include <functional>

#include <vulkan/vulkan.h>

namespace gpu {

using PassObserver = std::function<void(VkCommandBuffer cmd, const char* pass)>;

inline void passDone(const PassObserver& observer, VkCommandBuffer cmd, const char* pass) {
    if (observer) observer(cmd, pass);
}

}  // namespace gpu
