#include "model/mesh_builder.h"

#include <cassert>
#include <cmath>
#include <map>
#include <numbers>

namespace model {
namespace {

// The tube before its vertices are emitted: one logical vertex per ring corner, pole or cap centre,
// so normals can be averaged over all faces round a corner before material seams split it.
struct TubeGrid {
    std::vector<glm::vec3> positions;
    std::vector<std::size_t> ringOf;     // ring whose skin and material each logical vertex takes
    std::vector<glm::uvec3> triangles;   // logical vertex ids
    std::vector<std::size_t> materialRing;  // per triangle: ring whose material it takes
};

bool isPole(const Ring& ring) { return ring.radius.x == 0.0f && ring.radius.y == 0.0f; }

glm::vec3 tubeAxis(const std::vector<Ring>& rings, std::size_t i) {
    const std::size_t before = i == 0 ? 0 : i - 1, after = i + 1 == rings.size() ? i : i + 1;
    return glm::normalize(rings[after].center - rings[before].center);
}

// Adds ring i's corners to the grid and returns the first id; a pole ring adds one point.
std::uint32_t addRing(TubeGrid& grid, const Tube& tube, std::size_t i) {
    const Ring& ring = tube.rings[i];
    const std::uint32_t first = static_cast<std::uint32_t>(grid.positions.size());
    const int corners = isPole(ring) ? 1 : tube.segments;
    const glm::vec3 t = tubeAxis(tube.rings, i);
    const glm::vec3 u = glm::normalize(tube.side - t * glm::dot(tube.side, t));
    const glm::vec3 v = glm::cross(t, u);  // (u, v, t) right-handed: increasing angle turns round +t
    for (int j = 0; j < corners; ++j) {
        const float angle = 2.0f * std::numbers::pi_v<float> * (static_cast<float>(j) + 0.5f) /
                            static_cast<float>(tube.segments);
        grid.positions.push_back(ring.center + ring.radius.x * std::cos(angle) * u +
                                 ring.radius.y * std::sin(angle) * v);
        grid.ringOf.push_back(i);
    }
    return first;
}

std::uint32_t addPoint(TubeGrid& grid, glm::vec3 position, std::size_t ring) {
    grid.positions.push_back(position);
    grid.ringOf.push_back(ring);
    return static_cast<std::uint32_t>(grid.positions.size() - 1);
}

// A fan from ring corners to a centre point, wound to face away from the tube (towards -axis at the
// start, +axis at the end).
void addFan(TubeGrid& grid, std::uint32_t ring, std::uint32_t center, int segments, bool atEnd,
            std::size_t materialRing) {
    for (int j = 0; j < segments; ++j) {
        const std::uint32_t a = ring + j, b = ring + (j + 1) % segments;
        grid.triangles.push_back(atEnd ? glm::uvec3(a, b, center) : glm::uvec3(b, a, center));
        grid.materialRing.push_back(materialRing);
    }
}

void addBand(TubeGrid& grid, std::uint32_t lower, std::uint32_t upper, int segments, std::size_t materialRing) {
    for (int j = 0; j < segments; ++j) {
        const std::uint32_t a = lower + j, b = lower + (j + 1) % segments;
        const std::uint32_t c = upper + (j + 1) % segments, d = upper + j;
        grid.triangles.push_back({a, b, c});
        grid.triangles.push_back({a, c, d});
        grid.materialRing.push_back(materialRing);
        grid.materialRing.push_back(materialRing);
    }
}

TubeGrid buildGrid(const Tube& tube) {
    assert(tube.rings.size() >= 2 && tube.segments >= 3);
    TubeGrid grid;
    const std::size_t last = tube.rings.size() - 1;
    std::vector<std::uint32_t> firstIds;
    for (std::size_t i = 0; i <= last; ++i) firstIds.push_back(addRing(grid, tube, i));
    const bool startPole = isPole(tube.rings.front()), endPole = isPole(tube.rings.back());
    const std::size_t firstBand = startPole ? 1 : 0, bandsEnd = endPole ? last - 1 : last;
    for (std::size_t i = firstBand; i < bandsEnd; ++i) addBand(grid, firstIds[i], firstIds[i + 1], tube.segments, i);
    // A pole closes the tube smoothly; a flat cap gets its own copy of the rim so the cap shades
    // flat and the side stays round instead of both bending towards a 45-degree average.
    if (startPole) {
        addFan(grid, firstIds[1], firstIds[0], tube.segments, false, 0);
    } else {
        const std::uint32_t rim = addRing(grid, tube, 0);
        addFan(grid, rim, addPoint(grid, tube.rings.front().center, 0), tube.segments, false, 0);
    }
    if (endPole) {
        addFan(grid, firstIds[bandsEnd], firstIds[last], tube.segments, true, bandsEnd);
    } else {
        const std::uint32_t rim = addRing(grid, tube, last);
        addFan(grid, rim, addPoint(grid, tube.rings.back().center, last), tube.segments, true, last);
    }
    return grid;
}

std::vector<glm::vec3> averagedNormals(const TubeGrid& grid) {
    std::vector<glm::vec3> normals(grid.positions.size(), glm::vec3(0.0f));
    for (const glm::uvec3& tri : grid.triangles) {
        // The unnormalized cross product weights each face by its area.
        const glm::vec3 n = glm::cross(grid.positions[tri.y] - grid.positions[tri.x],
                                       grid.positions[tri.z] - grid.positions[tri.x]);
        normals[tri.x] += n;
        normals[tri.y] += n;
        normals[tri.z] += n;
    }
    for (glm::vec3& n : normals) n = glm::normalize(n);
    return normals;
}

std::uint32_t appendVertex(SkinnedModel& model, glm::vec3 position, glm::vec3 normal, std::uint32_t material,
                           Influences influences) {
    // Unused slots point at joint 0 so every index is valid whatever the weight.
    for (int k = 0; k < 4; ++k)
        if (influences.weights[k] == 0.0f) influences.joints[k] = 0u;
    gpu::SkinVertex vertex;
    vertex.position = glm::vec4(position, 1.0f);
    vertex.normal = glm::vec4(normal, static_cast<float>(material));
    vertex.joints = influences.joints;
    vertex.weights = influences.weights;
    model.vertices.push_back(vertex);
    return static_cast<std::uint32_t>(model.vertices.size() - 1);
}

}  // namespace

std::function<Influences(const glm::vec3&)> chainSkin(std::vector<std::uint32_t> joints,
                                                      std::vector<glm::vec3> positions, float band) {
    return [joints = std::move(joints), positions = std::move(positions), band](const glm::vec3& point) {
        return chainInfluences({joints, positions}, point, band);
    };
}

std::function<Influences(const glm::vec3&)> rigidSkin(std::uint32_t joint) {
    return [joint](const glm::vec3&) { return rigid(joint); };
}

void addTube(SkinnedModel& model, const Tube& tube) {
    const TubeGrid grid = buildGrid(tube);
    const std::vector<glm::vec3> normals = averagedNormals(grid);
    // A logical vertex on a colour edge is emitted once per material that touches it.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> emitted;
    for (std::size_t t = 0; t < grid.triangles.size(); ++t) {
        const std::uint32_t material = tube.rings[grid.materialRing[t]].material;
        for (int corner = 0; corner < 3; ++corner) {
            const std::uint32_t id = grid.triangles[t][corner];
            auto [it, fresh] = emitted.try_emplace({id, material}, 0u);
            if (fresh) {
                const Ring& ring = tube.rings[grid.ringOf[id]];
                it->second = appendVertex(model, grid.positions[id], normals[id], material, tube.skin(ring.center));
            }
            model.indices.push_back(it->second);
        }
    }
}

void addBox(SkinnedModel& model, const Box& box) {
    // Each corner is computed by one expression wherever it appears, so the faces meet bit for bit.
    auto corner = [&box](glm::vec3 signs) {
        return box.center + box.axes * (signs * box.halfExtent);
    };
    for (int k = 0; k < 3; ++k) {
        for (float sign : {1.0f, -1.0f}) {
            // (a, b, n) right-handed, so corners in the order below run counter-clockwise seen from n.
            const int a = sign > 0.0f ? (k + 1) % 3 : (k + 2) % 3;
            const int b = sign > 0.0f ? (k + 2) % 3 : (k + 1) % 3;
            const glm::vec3 n = sign * box.axes[k];
            std::uint32_t first = 0;
            for (glm::vec2 ab : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
                glm::vec3 signs;
                signs[k] = sign;
                signs[a] = ab.x;
                signs[b] = ab.y;
                const std::uint32_t index = appendVertex(model, corner(signs), n, box.material, box.skin);
                if (ab == glm::vec2(-1, -1)) first = index;
            }
            for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) model.indices.push_back(first + i);
        }
    }
}

void stretchVertices(SkinnedModel& model, glm::vec3 stretch) {
    for (gpu::SkinVertex& v : model.vertices) {
        v.position = glm::vec4(glm::vec3(v.position) * stretch, 1.0f);
        // Normals transform by the inverse transpose, which for a scale is the reciprocal.
        v.normal = glm::vec4(glm::normalize(glm::vec3(v.normal) / stretch), v.normal.w);
    }
}

}  // namespace model
