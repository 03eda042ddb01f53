#include "render/raster_mode.h"

#include "gpu/error.h"
#include "gpu/vulkan_context.h"

namespace render {

const char* rasterModeName(RasterMode mode) {
    switch (mode) {
        case RasterMode::Hardware: return "hardware";
        case RasterMode::Compute: return "compute";
        case RasterMode::Auto: return "auto";
    }
    return "hardware";
}

std::optional<RasterMode> parseRasterMode(std::string_view name) {
    for (const RasterMode mode : {RasterMode::Hardware, RasterMode::Compute, RasterMode::Auto})
        if (name == rasterModeName(mode)) return mode;
    return std::nullopt;
}

void requireComputeRaster(const gpu::VulkanContext& context) {
    if (!context.int64Atomics)
        throw gpu::Error("the compute rasterizer needs the features shaderInt64 and shaderBufferInt64Atomics, which " +
                             context.description.name + " lacks or the device was created without",
                         gpu::ErrorKind::Unsupported);
}

}  // namespace render
