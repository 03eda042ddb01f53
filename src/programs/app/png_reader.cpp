#include "app/png_reader.h"

#include <cstring>
#include <memory>

#include <stb/stb_image.h>

#include "app/error.h"

namespace app {

app::Rgba8Image readPng(const std::string& path) {
    int width = 0, height = 0, channels = 0;
    const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(stbi_load(path.c_str(), &width, &height, &channels, 4),
                                                           stbi_image_free);
    if (!pixels) throw app::Error("cannot read " + path + ": " + stbi_failure_reason());
    app::Rgba8Image image;
    image.width = static_cast<std::uint32_t>(width);
    image.height = static_cast<std::uint32_t>(height);
    image.pixels.resize(std::size_t{image.width} * image.height * 4);
    std::memcpy(image.pixels.data(), pixels.get(), image.pixels.size());
    return image;
}

}  // namespace app
