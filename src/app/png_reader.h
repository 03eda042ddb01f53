#pragma once
// Reads a PNG (any of its colour types) as RGBA8: what image-psnr compares.
#include <string>

#include "render/png_writer.h"

namespace app {

// Throws gpu::Error naming the file when it cannot be read or decoded.
render::Rgba8Image readPng(const std::string& path);

}  // namespace app
