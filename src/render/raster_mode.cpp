#include "render/raster_mode.h"

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

}  // namespace render
