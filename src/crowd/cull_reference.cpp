#include "crowd/cull_reference.h"

#include <algorithm>
#include <cmath>

#include "crowd/farthest_first.h"

namespace crowd {

std::array<glm::vec4, 6> frustumPlanes(const glm::mat4& m) {
    // Gribb and Hartmann: each plane is a sum or difference of rows of the matrix (glm is column-major).
    auto row = [&](int i) { return glm::vec4(m[0][i], m[1][i], m[2][i], m[3][i]); };
    std::array<glm::vec4, 6> planes = {row(3) + row(0), row(3) - row(0), row(3) + row(1),
                                       row(3) - row(1), row(2),          row(3) - row(2)};
    for (glm::vec4& p : planes) p /= glm::length(glm::vec3(p));
    return planes;
}

glm::vec4 worldSphere(const gpu::CharacterRecord& character, const gpu::ModelRecord& model) {
    const float scale = character.tint.w;
    const float s = std::sin(character.placement.w);
    const float c = std::cos(character.placement.w);
    const glm::vec3 local = glm::vec3(model.sphere) * scale;
    const glm::vec3 turned(c * local.x + s * local.z, local.y, c * local.z - s * local.x);
    return glm::vec4(glm::vec3(character.placement) + turned, model.sphere.w * scale);
}

bool sphereInFrustum(const glm::vec4 planes[6], const glm::vec4& sphere) {
    for (int i = 0; i < 6; ++i)
        if (glm::dot(glm::vec3(planes[i]), glm::vec3(sphere)) + planes[i].w < -sphere.w) return false;
    return true;
}

bool casterInFrustum(const glm::vec4 planes[6], const glm::vec4& sphere, const glm::vec3& towardsLight) {
    for (int i = 0; i < 6; ++i)
        if (glm::dot(glm::vec3(planes[i]), glm::vec3(sphere)) + planes[i].w < -sphere.w &&
            glm::dot(glm::vec3(planes[i]), towardsLight) >= 0.0f)
            return false;
    return true;
}

float projectedDiameter(const glm::vec4& sphere, const glm::vec4& camera) {
    const float d = glm::distance(glm::vec3(sphere), glm::vec3(camera));
    return d > sphere.w ? 2.0f * sphere.w * camera.w / d : 3.0e38f;
}

std::uint32_t lodForSize(float size, const glm::vec4& lod, float scale) {
    return (size < lod.x * scale ? 1u : 0u) + (size < lod.y * scale ? 1u : 0u) + (size < lod.w * scale ? 1u : 0u);
}

std::uint32_t chooseLod(float size, std::uint32_t previous, const glm::vec4& lod) {
    if (previous == 0u) return lodForSize(size, lod, 1.0f);
    const std::uint32_t finest = lodForSize(size, lod, 1.0f - lod.z);
    const std::uint32_t coarsest = lodForSize(size, lod, 1.0f + lod.z);
    return std::clamp(previous - 1u, finest, coarsest);
}

namespace {

// A character that qualifies for a mesh level: in view (or a caster), at LOD 0-2.
struct MeshCandidate {
    std::uint32_t bucket;
    bool drawnIfDemoted;  // in view: drawn as an impostor if the cap demotes it
};

}  // namespace

VisibleLists cullOnCpu(const gpu::CullUniforms& cull, std::span<const gpu::CharacterRecord> characters,
                       std::span<const gpu::ModelRecord> models, std::span<std::uint32_t> lodState,
                       std::vector<std::uint32_t>* impostors, std::uint32_t* demoted) {
    VisibleLists lists(models.size() * LOD_COUNT);
    std::vector<MeshCandidate> candidates;
    std::vector<SizedCharacter> sizes;
    // Impostors cast no shadow, so only those in view are kept.
    auto drawnAsImpostor = [&](const glm::vec4& sphere) { return cull.flags.y == 0u || sphereInFrustum(cull.planes, sphere); };
    for (std::uint32_t c = 0; c < characters.size(); ++c) {
        const gpu::CharacterRecord& character = characters[c];
        const glm::vec4 sphere = worldSphere(character, models[character.ids.x]);
        const bool visible = cull.flags.y == 0u ||
                             (cull.limits.y != 0u ? casterInFrustum(cull.planes, sphere, glm::vec3(cull.light))
                                                  : sphereInFrustum(cull.planes, sphere));
        const float size = projectedDiameter(sphere, cull.camera);
        std::uint32_t lod = 0;
        if (cull.flags.z != 0u) lod = chooseLod(size, lodState[c], cull.lod);
        lodState[c] = cull.flags.z != 0u ? lod + 1u : 0u;
        if (lod == IMPOSTOR_LEVEL) {
            if (impostors && drawnAsImpostor(sphere)) impostors->push_back(c);
            continue;
        }
        if (!visible) continue;
        candidates.push_back({character.ids.x * LOD_COUNT + lod, drawnAsImpostor(sphere)});
        sizes.push_back({c, size});
    }
    // Over the cap, the smallest on screen are demoted (crowd/farthest_first.h).
    const std::vector<bool> kept = cull.limits.z != 0u ? keepsMesh(sizes, cull.limits.z)
                                                       : std::vector<bool>(candidates.size(), true);
    if (demoted) *demoted = static_cast<std::uint32_t>(std::count(kept.begin(), kept.end(), false));
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        if (kept[i]) lists[candidates[i].bucket].push_back(sizes[i].character);
        else if (impostors && candidates[i].drawnIfDemoted) impostors->push_back(sizes[i].character);
    }
    if (impostors) std::sort(impostors->begin(), impostors->end());
    return lists;
}

}  // namespace crowd
