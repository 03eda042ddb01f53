#include "api/renderer_arguments.h"

#include <string>

namespace crowdgpu::detail {
namespace {

// Refuses `value` unless it is below `count` (the enums are numbered from 0, as the C API's).
template <class E>
void checkEnum(const char* call, const char* argument, E value, int count, const char* names) {
    const int v = static_cast<int>(value);
    if (v < 0 || v >= count)
        throw Error(ErrorCode::InvalidArgument, std::string(call) + ": " + argument + " " + std::to_string(v) +
                                                    " is not one of " + names);
}

}  // namespace

void checkMethod(const char* call, Method method) {
    checkEnum(call, "method", method, 6,
              "two-pass (0), two-pass-direct (1), vs (2), vs-instanced (3), compute (4), static (5)");
}

void checkAnimation(const char* call, Animation animation) {
    checkEnum(call, "animation", animation, 2, "gpu (0), cpu (1)");
}

void checkCulling(const char* call, Culling culling) { checkEnum(call, "culling", culling, 3, "gpu (0), cpu (1), off (2)"); }

void checkShadowRaster(const char* call, ShadowRaster raster) {
    checkEnum(call, "shadow raster", raster, 2, "hardware (0), compute (1)");
}

void checkRaster(const char* call, Raster raster) {
    checkEnum(call, "raster mode", raster, 3, "hardware (0), compute (1), auto (2)");
}

void checkSettingEnums(const RendererSettings& s) {
    checkMethod("RendererSettings", s.method);
    checkAnimation("RendererSettings", s.animation);
    checkCulling("RendererSettings", s.culling);
    checkShadowRaster("RendererSettings", s.shadowRaster);
    checkRaster("RendererSettings", s.raster);
}

void checkPhysicalDeviceGiven(const char* call, VkPhysicalDevice physicalDevice) {
    if (physicalDevice == VK_NULL_HANDLE)
        throw Error(ErrorCode::InvalidArgument, std::string(call) + ": no physical device given (VK_NULL_HANDLE)");
}

}  // namespace crowdgpu::detail
