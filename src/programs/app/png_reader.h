#pragma once
// Reads a PNG (any of its colour types) as RGBA8: what image-psnr compares.
#include <string>

#include "app/png_writer.h"

namespace app {

// Throws app::Error naming the file when it cannot be read or decoded.
app::Rgba8Image readPng(const std::string& path);

}  // namespace app
