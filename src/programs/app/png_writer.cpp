#include "app/png_writer.h"

#include <stb/stb_image_write.h>

#include "app/error.h"
#include "io/output_file.h"

namespace app {
namespace {

void append(void* context, void* data, int size) {
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    static_cast<std::vector<std::uint8_t>*>(context)->insert(static_cast<std::vector<std::uint8_t>*>(context)->end(),
                                                             bytes, bytes + size);
}

}  // namespace

void writePng(const std::string& path, const Rgba8Image& image) {
    std::vector<std::uint8_t> png;
    const int ok = stbi_write_png_to_func(&append, &png, static_cast<int>(image.width), static_cast<int>(image.height),
                                          4, image.pixels.data(), static_cast<int>(image.width * 4));
    if (!ok) throw Error("cannot encode PNG " + path);
    io::writeFile(path, png);
}

}  // namespace app
