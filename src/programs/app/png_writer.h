#pragma once
// Writes RGBA8 pixels as a PNG file.
#include <cstdint>
#include <string>
#include <vector>

namespace app {

struct Rgba8Image {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<std::uint8_t> pixels;  // width * height * 4, rows top to bottom
};

// Encodes in memory, then writes through io::writeFile (complete file or none). Throws app::Error
// naming the path when it cannot be written.
void writePng(const std::string& path, const Rgba8Image& image);

}  // namespace app
