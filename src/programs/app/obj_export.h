#pragma once
// A posed mesh as Wavefront OBJ, for checking poses in any modelling tool or against another
// glTF implementation.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include <glm/glm.hpp>

namespace app {

// Writes one object: a 'v' and a 'vn' line per vertex (9 significant digits, enough to read each
// float back exactly) and an 'f a//a b//b c//c' line per triangle, through io::writeFile (the whole
// file or none). Throws app::Error naming the file when it cannot be written.
void writeObj(const std::filesystem::path& path, const std::string& objectName, std::span<const glm::dvec3> positions,
              std::span<const glm::dvec3> normals, std::span<const std::uint32_t> triangles);

}  // namespace app
