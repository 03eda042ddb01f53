#include "model/lod_weld.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

#include <meshoptimizer.h>

namespace model {
namespace {

using Triangles = std::vector<std::uint32_t>;

// A vertex's skin as welding compares it: influences sorted by joint, weights rounded to 1/4096, no
// zero-weight slots. Exporters write one skin with differing float noise or unused joint slots
// (RiggedSimple, along each of its seams), which compared bit for bit would lock the whole seam.
struct SkinKey {
    std::array<std::uint32_t, MAX_INFLUENCES> joints{};
    std::array<std::uint32_t, MAX_INFLUENCES> weights{};
};

std::vector<SkinKey> skinKeys(const std::vector<gpu::SkinVertex>& vertices) {
    std::vector<SkinKey> keys(vertices.size());
    for (std::size_t v = 0; v < vertices.size(); ++v) {
        std::array<std::pair<std::uint32_t, std::uint32_t>, MAX_INFLUENCES> influences{};
        for (int i = 0; i < MAX_INFLUENCES; ++i) {
            const auto weight = static_cast<std::uint32_t>(std::lround(vertices[v].weights[i] * 4096.0f));
            if (weight > 0) influences[i] = {vertices[v].joints[i], weight};
        }
        std::sort(influences.begin(), influences.end());
        for (int i = 0; i < MAX_INFLUENCES; ++i)
            keys[v].joints[i] = influences[i].first, keys[v].weights[i] = influences[i].second;
    }
    return keys;
}

// Merges the vertices `triangles` uses that agree in position, skin, material, uv and (when kept)
// normal.
WeldedMesh weldEqual(const SkinnedModel& model, const Triangles& triangles, bool keepNormals) {
    const std::vector<gpu::SkinVertex>& vertices = model.vertices;
    const std::vector<SkinKey> skins = skinKeys(vertices);
    std::vector<meshopt_Stream> streams = {
        {&vertices[0].position, sizeof(glm::vec3), sizeof(gpu::SkinVertex)},
        // The normal and material (its w), or the material alone.
        {keepNormals ? &vertices[0].normal.x : &vertices[0].normal.w, keepNormals ? sizeof(glm::vec4) : sizeof(float),
         sizeof(gpu::SkinVertex)},
        {skins.data(), sizeof(SkinKey), sizeof(SkinKey)},
    };
    if (!model.uvs.empty()) streams.push_back({model.uvs.data(), sizeof(glm::vec2), sizeof(glm::vec2)});
    std::vector<unsigned int> remap(vertices.size());
    const std::size_t welded = meshopt_generateVertexRemapMulti(remap.data(), triangles.data(), triangles.size(),
                                                                vertices.size(), streams.data(), streams.size());
    WeldedMesh mesh;
    mesh.positions.resize(welded);
    mesh.members.resize(welded);
    for (std::uint32_t v = 0; v < vertices.size(); ++v) {
        if (remap[v] == ~0u) continue;  // not used by these triangles
        mesh.positions[remap[v]] = glm::vec3(vertices[v].position);
        mesh.members[remap[v]].push_back(v);
    }
    mesh.indices.resize(triangles.size());
    meshopt_remapIndexBuffer(mesh.indices.data(), triangles.data(), triangles.size(), remap.data());
    return mesh;
}

// The region a triangle belongs to: that of its corner held most firmly by one joint (the corner whose
// largest weight is the largest; ties: the first corner). Along a limb the weights pass from one bone
// to the next over a few rings; the band of triangles between the ring where the dominant joint changes
// and its neighbour goes to the side of the firmer ring, so the boundary, which the simplifier keeps,
// is the ring nearer an even blend: the crease of the bend (the elbow ring, not the one above it). All
// triangles of a band agree, so a boundary is a clean ring, not a zigzag across the band whose every
// vertex would be locked.
std::uint32_t region(const SkinnedModel& model, const std::vector<std::uint32_t>& jointRegions,
                     const std::uint32_t* triangle) {
    std::uint32_t joint = 0;
    float firmest = -1.0f;
    for (int k = 0; k < 3; ++k) {
        const gpu::SkinVertex& v = model.vertices[triangle[k]];
        for (int i = 0; i < MAX_INFLUENCES; ++i)
            if (v.weights[i] > firmest) firmest = v.weights[i], joint = v.joints[i];
    }
    return joint < jointRegions.size() ? jointRegions[joint] : joint;
}

// Gives every welded vertex one copy per region round it, so region boundaries become seams.
WeldedMesh splitAtRegionBoundaries(const SkinnedModel& model, const std::vector<std::uint32_t>& jointRegions,
                                   const Triangles& triangles, const WeldedMesh& mesh) {
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> copies(mesh.positions.size());  // (region, id)
    WeldedMesh split;
    split.indices.reserve(mesh.indices.size());
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const std::uint32_t own = region(model, jointRegions, &triangles[t]);
        for (std::size_t k = t; k < t + 3; ++k) {
            std::vector<std::pair<std::uint32_t, std::uint32_t>>& vertexCopies = copies[mesh.indices[k]];
            auto copy = std::find_if(vertexCopies.begin(), vertexCopies.end(), [&](const auto& c) { return c.first == own; });
            if (copy == vertexCopies.end()) {
                vertexCopies.push_back({own, static_cast<std::uint32_t>(split.positions.size())});
                copy = vertexCopies.end() - 1;
                split.positions.push_back(mesh.positions[mesh.indices[k]]);
                split.members.push_back(mesh.members[mesh.indices[k]]);
            }
            split.indices.push_back(copy->second);
        }
    }
    return split;
}

std::array<std::uint32_t, 3> chooseCorners(const SkinnedModel& model, const WeldedMesh& mesh,
                                           const std::uint32_t* triangle) {
    const glm::vec3 a = mesh.positions[triangle[0]], b = mesh.positions[triangle[1]], c = mesh.positions[triangle[2]];
    const glm::vec3 face = glm::cross(b - a, c - a);
    auto alignment = [&](std::uint32_t v) { return glm::dot(glm::vec3(model.vertices[v].normal), face); };
    std::array<std::uint32_t, 3> corners{};
    for (int k = 0; k < 3; ++k) {
        corners[k] = mesh.members[triangle[k]][0];
        for (std::uint32_t v : mesh.members[triangle[k]])
            if (alignment(v) > alignment(corners[k])) corners[k] = v;
    }
    return corners;
}

// A triangle whose edges are numerically parallel has no area and no normal: it draws nothing.
bool hasArea(const SkinnedModel& model, const std::array<std::uint32_t, 3>& t) {
    const glm::dvec3 a(model.vertices[t[0]].position), b(model.vertices[t[1]].position),
        c(model.vertices[t[2]].position);
    const glm::dvec3 u = b - a, v = c - a;
    return glm::length(glm::cross(u, v)) > 1e-6 * glm::length(u) * glm::length(v);
}

// The triangle's corners in ascending order, and whether that order keeps its winding.
std::pair<std::array<std::uint32_t, 3>, bool> sortedCorners(const std::uint32_t* t) {
    std::array<std::uint32_t, 3> sorted = {t[0], t[1], t[2]};
    // An even permutation (a rotation) keeps the winding, an odd one reverses it: count the swaps.
    bool even = true;
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2 - i; ++j)
            if (sorted[j] > sorted[j + 1]) std::swap(sorted[j], sorted[j + 1]), even = !even;
    return {sorted, even};
}

// Leaves out repeated triangles, and both triangles of a pair that is one triangle both ways round:
// that is what meshoptimizer collapses a closed part to when the budget asks for fewer triangles than
// its last tetrahedron (a flat sheet with no inside, where the part was).
Triangles withoutFlattenedParts(const Triangles& welded) {
    std::map<std::array<std::uint32_t, 3>, std::pair<std::size_t, bool>> seen;  // corners -> (first, winding)
    std::vector<bool> keep(welded.size() / 3, true);
    for (std::size_t t = 0; t < keep.size(); ++t) {
        const auto [corners, even] = sortedCorners(&welded[3 * t]);
        const auto [it, inserted] = seen.try_emplace(corners, t, even);
        if (inserted) continue;
        keep[t] = false;
        if (it->second.second != even) keep[it->second.first] = false;
    }
    Triangles kept;
    for (std::size_t t = 0; t < keep.size(); ++t)
        if (keep[t]) kept.insert(kept.end(), welded.begin() + 3 * t, welded.begin() + 3 * t + 3);
    return kept;
}

}  // namespace

WeldedMesh weld(const SkinnedModel& model, const Triangles& triangles, LodSeams seams,
                const std::vector<std::uint32_t>& jointRegions) {
    const WeldedMesh mesh = weldEqual(model, triangles, seams.normals);
    return seams.bends ? splitAtRegionBoundaries(model, jointRegions, triangles, mesh) : mesh;
}

Triangles unweld(const SkinnedModel& model, const WeldedMesh& mesh, const Triangles& welded) {
    const Triangles kept = withoutFlattenedParts(welded);
    Triangles triangles;
    triangles.reserve(kept.size());
    for (std::size_t i = 0; i + 2 < kept.size(); i += 3) {
        const std::array<std::uint32_t, 3> t = chooseCorners(model, mesh, &kept[i]);
        if (hasArea(model, t)) triangles.insert(triangles.end(), t.begin(), t.end());
    }
    return triangles;
}

}  // namespace model
