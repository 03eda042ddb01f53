#pragma once
// The renderer API's arguments that are checked before anything reaches Vulkan: the settings' enum
// values (a C host may pass any integer), the physical device of the queries, a frame's time. Each
// throws Error(InvalidArgument) in one line naming the argument and the value. The target's formats
// are checked against the device in device_requirements.h.
#include <vulkan/vulkan.h>

#include "crowdgpu/renderer.hpp"

namespace crowdgpu::detail {

// method, animation, culling, shadowRaster and raster are values of their enums.
void checkSettingEnums(const RendererSettings& settings);
void checkMethod(const char* call, Method method);
void checkAnimation(const char* call, Animation animation);
void checkCulling(const char* call, Culling culling);
void checkShadowRaster(const char* call, ShadowRaster raster);
void checkRaster(const char* call, Raster raster);
// A query's physical device is given (memoryNeeded, checkDeviceLimits, viewportProblem).
void checkPhysicalDeviceGiven(const char* call, VkPhysicalDevice physicalDevice);

}  // namespace crowdgpu::detail
