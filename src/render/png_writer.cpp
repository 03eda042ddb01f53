#include "render/png_writer.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <stb/stb_image_write.h>

#include "gpu/vulkan_error.h"

namespace render {

void checkWritable(const std::string& path) {
    std::FILE* existing = std::fopen(path.c_str(), "rb");
    if (existing) std::fclose(existing);
    std::FILE* file = std::fopen(path.c_str(), "ab");
    if (!file) throw gpu::Error("cannot write " + path + ": " + std::strerror(errno));
    std::fclose(file);
    if (!existing) std::remove(path.c_str());  // leave no empty file behind if the run fails later
}

void writePng(const std::string& path, const Rgba8Image& image) {
    const int ok = stbi_write_png(path.c_str(), static_cast<int>(image.width), static_cast<int>(image.height), 4,
                                  image.pixels.data(), static_cast<int>(image.width * 4));
    if (!ok) throw gpu::Error("cannot write PNG " + path);
}

}  // namespace render
