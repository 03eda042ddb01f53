#include "support/vertex_matching.h"

#include <cstring>
#include <deque>
#include <map>
#include <string>

namespace test {
namespace {

// A vertex's bytes: SkinVertex has only 16-byte members, so no padding to compare.
std::string vertexKey(const model::SkinnedModel& m, std::size_t v) {
    std::string key(reinterpret_cast<const char*>(&m.vertices[v]), sizeof(gpu::SkinVertex));
    if (!m.uvs.empty()) key.append(reinterpret_cast<const char*>(&m.uvs[v]), sizeof(glm::vec2));
    return key;
}

}  // namespace

std::vector<std::uint32_t> originalVertexOf(const model::SkinnedModel& original, const model::SkinnedModel& reordered) {
    std::map<std::string, std::deque<std::uint32_t>> unmatched;
    for (std::uint32_t v = 0; v < original.vertices.size(); ++v) unmatched[vertexKey(original, v)].push_back(v);
    std::vector<std::uint32_t> result;
    for (std::size_t v = 0; v < reordered.vertices.size(); ++v) {
        std::deque<std::uint32_t>& copies = unmatched[vertexKey(reordered, v)];
        result.push_back(copies.empty() ? ~0u : copies.front());
        if (!copies.empty()) copies.pop_front();
    }
    return result;
}

}  // namespace test
