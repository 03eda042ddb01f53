#include "crowd/cull_reference.h"

#include <algorithm>
#include <bit>
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

std::uint32_t fadedLod(float size, const glm::vec4& lod) {
    return lodForSize(size, glm::vec4(lod.x, lod.y, lod.z, lod.w * (1.0f - lod.z)), 1.0f);
}

std::uint32_t fadeShare(float size, std::uint32_t finer, const glm::vec4& lod) {
    const float threshold = finer == 0u ? lod.x : finer == 1u ? lod.y : finer == 2u ? lod.w : 0.0f;
    if (threshold <= 0.0f || lod.z <= 0.0f) return 0u;
    const float top = threshold * (1.0f + (finer == 2u ? lod.z : 2.0f * lod.z));
    const float share = std::clamp((top - size) / (2.0f * lod.z * threshold), 0.0f, 1.0f);
    return static_cast<std::uint32_t>(std::floor(share * static_cast<float>(FADE_STEPS) + 0.5f));
}

std::uint32_t cascadesReached(const glm::vec4& sphere, const gpu::CullUniforms& cull) {
    std::uint32_t reached = 0u;
    for (std::uint32_t k = 0; k < cull.shadowFlags.z; ++k)
        if (sphereInFrustum(cull.cascadePlanes + 6 * k, sphere)) reached |= 1u << k;
    return reached;
}

std::uint32_t shadowState(const glm::vec4& sphere, std::uint32_t viewLod, bool inView, const gpu::CullUniforms& cull) {
    std::uint32_t state = inView ? SHADOW_IN_VIEW_BIT : 0u;
    const bool shadowLod = cull.shadowFlags.x != 0u && cull.flags.z != 0u;
    std::uint32_t cascades = cull.limits.y != 0u ? cascadesReached(sphere, cull) : 0u;
    const int finest = cascades != 0u ? std::countr_zero(cascades) : 0;
    const float texels = 2.0f * sphere.w * cull.cascadeTexels[finest];
    std::uint32_t level = viewLod;
    if (shadowLod && viewLod != IMPOSTOR_LEVEL)
        level = std::max(viewLod, (texels < cull.shadow.y ? 1u : 0u) + (texels < cull.shadow.z ? 1u : 0u));
    state |= level;
    if (cull.limits.y == 0u) return state;
    if (cull.flags.y == 0u) cascades = (1u << cull.shadowFlags.z) - 1u;
    const bool reaches =
        cull.flags.y == 0u || (casterInFrustum(cull.planes, sphere, glm::vec3(cull.light)) && cascades != 0u);
    if (reaches && !(shadowLod && texels < cull.shadow.w)) state |= SHADOW_CASTS_BIT | (cascades << SHADOW_CASCADE_SHIFT);
    return state;
}

namespace {

// A character that qualifies for a mesh level: in view or a caster, at LOD 0-2.
struct MeshCandidate {
    std::uint32_t character;
    std::uint32_t viewLod;
};

}  // namespace

VisibleLists cullOnCpu(const gpu::CullUniforms& cull, std::span<const gpu::CharacterRecord> characters,
                       std::span<const gpu::ModelRecord> models, std::span<std::uint32_t> lodState,
                       std::vector<std::uint32_t>* impostors, std::uint32_t* demoted, ShadowLists* shadows) {
    VisibleLists lists(models.size() * LOD_COUNT);
    ShadowLists ownShadows;
    ShadowLists& shadow = shadows ? *shadows : ownShadows;
    shadow.casters.assign(models.size() * LOD_COUNT, {});
    shadow.impostors.clear();
    shadow.states.assign(characters.size(), 0u);
    std::vector<MeshCandidate> candidates;
    std::vector<SizedCharacter> sizes;
    // As cull_lists.glsl.inc places them: in view at the view's level, a caster out of view at its
    // shadow level; casters also in their shadow level's list; impostors drawn in view, casting a quad.
    auto placeMesh = [&](std::uint32_t c, std::uint32_t viewLod) {
        const std::uint32_t state = shadow.states[c];
        const std::uint32_t model = characters[c].ids.x;
        const std::uint32_t shadowLevel = state & SHADOW_LEVEL_MASK;
        const bool inView = (state & SHADOW_IN_VIEW_BIT) != 0u;
        lists[model * LOD_COUNT + (inView ? viewLod : shadowLevel)].push_back(c);
        if (impostors && inView && viewLod == LOD_COUNT - 1u && (state >> FADE_SHIFT) != 0u) impostors->push_back(c);
        if (state & SHADOW_CASTS_BIT) shadow.casters[model * LOD_COUNT + shadowLevel].push_back(c);
    };
    auto placeImpostor = [&](std::uint32_t c) {
        if (impostors && (shadow.states[c] & SHADOW_IN_VIEW_BIT)) impostors->push_back(c);
        if (shadow.states[c] & SHADOW_CASTS_BIT) shadow.impostors.push_back(c);
    };
    for (std::uint32_t c = 0; c < characters.size(); ++c) {
        const gpu::CharacterRecord& character = characters[c];
        if (!(character.tint.w > 0.0f)) {  // a free slot, as cull.comp skips it
            lodState[c] = 0u;
            shadow.states[c] = 0u;
            continue;
        }
        const glm::vec4 sphere = worldSphere(character, models[character.ids.x]);
        const bool inView = cull.flags.y == 0u || sphereInFrustum(cull.planes, sphere);
        const float size = projectedDiameter(sphere, cull.camera);
        std::uint32_t lod = 0;
        const bool fades = cull.flags.z != 0u && cull.fade.x != 0u;
        if (cull.flags.z != 0u) lod = fades ? fadedLod(size, cull.lod) : chooseLod(size, lodState[c], cull.lod);
        lodState[c] = cull.flags.z != 0u ? lod + 1u : 0u;
        shadow.states[c] = shadowState(sphere, lod, inView, cull);
        if (fades) shadow.states[c] |= fadeShare(size, lod, cull.lod) << FADE_SHIFT;
        if (lod == IMPOSTOR_LEVEL) {
            placeImpostor(c);
            continue;
        }
        if (!inView && !(shadow.states[c] & SHADOW_CASTS_BIT)) continue;
        candidates.push_back({c, lod});
        sizes.push_back({c, size});
    }
    // Over the cap, the smallest on screen are demoted (crowd/farthest_first.h).
    const std::vector<bool> kept = cull.limits.z != 0u ? keepsMesh(sizes, cull.limits.z)
                                                       : std::vector<bool>(candidates.size(), true);
    if (demoted) *demoted = static_cast<std::uint32_t>(std::count(kept.begin(), kept.end(), false));
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        if (kept[i]) {
            placeMesh(candidates[i].character, candidates[i].viewLod);
        } else {
            shadow.states[candidates[i].character] &= (1u << FADE_SHIFT) - 1u;  // an impostor only, drawn whole
            placeImpostor(candidates[i].character);
        }
    }
    if (impostors) std::sort(impostors->begin(), impostors->end());
    std::sort(shadow.impostors.begin(), shadow.impostors.end());
    for (std::vector<std::uint32_t>& list : lists) std::sort(list.begin(), list.end());
    for (std::vector<std::uint32_t>& list : shadow.casters) std::sort(list.begin(), list.end());
    return lists;
}

}  // namespace crowd
