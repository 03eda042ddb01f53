#include "model/obj_export.h"

#include <cstdio>
#include <memory>

#include "gpu/vulkan_error.h"

namespace model {

void writeObj(const std::filesystem::path& path, const std::string& objectName, std::span<const glm::dvec3> positions,
              std::span<const glm::dvec3> normals, std::span<const std::uint32_t> triangles) {
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "w"), &std::fclose);
    if (!file) throw gpu::Error(path.string() + ": cannot open for writing");
    std::FILE* f = file.get();
    std::fprintf(f, "# %zu vertices, %zu triangles\no %s\n", positions.size(), triangles.size() / 3,
                 objectName.c_str());
    for (const glm::dvec3& p : positions) std::fprintf(f, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
    for (const glm::dvec3& n : normals) std::fprintf(f, "vn %.9g %.9g %.9g\n", n.x, n.y, n.z);
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const std::uint32_t a = triangles[t] + 1, b = triangles[t + 1] + 1,
                            c = triangles[t + 2] + 1;  // OBJ counts from 1
        std::fprintf(f, "f %u//%u %u//%u %u//%u\n", a, a, b, b, c, c);
    }
    if (std::ferror(f) || std::fflush(f) != 0) throw gpu::Error(path.string() + ": write failed (disk full?)");
}

}  // namespace model
