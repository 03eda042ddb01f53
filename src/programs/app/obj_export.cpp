#include "app/obj_export.h"

#include <cstdio>

#include "io/output_file.h"

namespace app {
namespace {

template <typename... Args>
void appendLine(std::string& text, const char* format, Args... args) {
    char line[160];
    const int length = std::snprintf(line, sizeof line, format, args...);
    text.append(line, static_cast<std::size_t>(std::min<int>(length, sizeof line - 1)));
}

}  // namespace

void writeObj(const std::filesystem::path& path, const std::string& objectName, std::span<const glm::dvec3> positions,
              std::span<const glm::dvec3> normals, std::span<const std::uint32_t> triangles) {
    std::string text = "# " + std::to_string(positions.size()) + " vertices, " +
                       std::to_string(triangles.size() / 3) + " triangles\no " + objectName + "\n";
    for (const glm::dvec3& p : positions) appendLine(text, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
    for (const glm::dvec3& n : normals) appendLine(text, "vn %.9g %.9g %.9g\n", n.x, n.y, n.z);
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const std::uint32_t a = triangles[t] + 1, b = triangles[t + 1] + 1,
                            c = triangles[t + 2] + 1;  // OBJ counts from 1
        appendLine(text, "f %u//%u %u//%u %u//%u\n", a, a, b, b, c, c);
    }
    io::writeFile(path, text);
}

}  // namespace app
