#include "model/lod_builder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <meshoptimizer.h>

#include "model/bend_regions.h"
#include "model/lod_weld.h"

namespace model {
namespace {

// The paper's soldier: 1,084, 544 and 312 polygons.
constexpr std::array<double, kLodLevels> kLevelRatio = {1.0, 544.0 / 1084.0, 312.0 / 1084.0};

// How far over its budget a level may end before the next, less careful way is tried.
constexpr double kBudgetTolerance = 0.10;

// The seams each attempt keeps, most careful first (see LodSeams): each one gives up what blocked
// the one before when it could not reach the budget.
constexpr std::array<LodSeams, 3> kAttempts = {{{true, true}, {false, true}, {false, false}}};

using Triangles = std::vector<std::uint32_t>;

// A level is a polygon budget, as in the paper, not an error bound: the simplifier collapses the
// cheapest edges first with its error left unbounded, so it stops only at the budget or where
// topology forbids any further collapse (seams meeting, a part down to a tetrahedron).
Triangles simplifyTopology(const SkinnedModel& model, const WeldedMesh& mesh, std::size_t targetTriangles) {
    Triangles welded(mesh.indices.size());
    welded.resize(meshopt_simplify(welded.data(), mesh.indices.data(), mesh.indices.size(), &mesh.positions[0].x,
                                   mesh.positions.size(), sizeof(glm::vec3), targetTriangles * 3,
                                   std::numeric_limits<float>::max(), 0, nullptr));
    return unweld(model, mesh, welded);
}

// Vertex clustering, which ignores topology and seams: it reaches any budget, at the price of holes,
// merged parts and smeared textures, so it is the last resort.
Triangles simplifySloppy(const SkinnedModel& model, const WeldedMesh& mesh, std::size_t targetTriangles) {
    Triangles welded(mesh.indices.size());
    welded.resize(meshopt_simplifySloppy(welded.data(), mesh.indices.data(), mesh.indices.size(), &mesh.positions[0].x,
                                         mesh.positions.size(), sizeof(glm::vec3), targetTriangles * 3,
                                         std::numeric_limits<float>::max(), nullptr));
    return unweld(model, mesh, welded);
}

bool withinBudget(const Triangles& level, std::size_t targetTriangles) {
    return static_cast<double>(level.size() / 3) <= static_cast<double>(targetTriangles) * (1.0 + kBudgetTolerance);
}

std::size_t distanceToBudget(const Triangles& level, std::size_t targetTriangles) {
    const std::size_t triangles = level.size() / 3;
    return triangles > targetTriangles ? triangles - targetTriangles : targetTriangles - triangles;
}

// The level below `parent`: the first attempt that ends at most 10 % over the budget; when none does,
// whichever of them and sloppy clustering came nearest it. A level that cannot get nearer the budget
// than its parent, or that would be empty, is its parent again: more triangles than the budget are
// better than a character with holes, or none.
Triangles simplifyLevel(const SkinnedModel& model, const std::vector<std::uint32_t>& jointRegions,
                        const Triangles& parent, std::size_t targetTriangles) {
    if (parent.empty()) return parent;
    Triangles best = parent;
    auto consider = [&](Triangles level) {
        if (!level.empty() && distanceToBudget(level, targetTriangles) < distanceToBudget(best, targetTriangles))
            best = std::move(level);
        return withinBudget(best, targetTriangles);
    };
    for (const LodSeams& seams : kAttempts)
        if (consider(simplifyTopology(model, weld(model, parent, seams, jointRegions), targetTriangles))) return best;
    consider(simplifySloppy(model, weld(model, parent, kAttempts.back(), jointRegions), targetTriangles));
    return best;
}

// Reorders the vertices so that each level's come first: the coarsest level's, then those the next
// finer level adds, and so on, and last any the full mesh does not use. Within a group the loaded
// order is kept: the builders and glTF exporters lay vertices out part by part, which the skinning
// passes (they run over vertices in order) and the vertex fetch of the draw already benefit from,
// and a stable partition is easy to check. (A per-level meshopt_optimizeVertexFetch would have to be
// confined to each group anyway, to keep the prefixes.) Returns each level's vertex count.
std::array<std::uint32_t, kLodLevels> reorderVertices(SkinnedModel& model, std::array<Triangles, kLodLevels>& levels) {
    const std::size_t count = model.vertices.size();
    // group[v]: kLodLevels - 1 - (the coarsest level using v), or kLodLevels when no level does.
    std::vector<std::size_t> group(count, kLodLevels);
    for (std::size_t l = 0; l < kLodLevels; ++l)
        for (std::uint32_t v : levels[l]) group[v] = kLodLevels - 1 - l;
    std::vector<std::uint32_t> newToOld, oldToNew(count);
    newToOld.reserve(count);
    std::array<std::uint32_t, kLodLevels> vertexCount{};
    for (std::size_t g = 0; g <= kLodLevels; ++g) {
        for (std::uint32_t v = 0; v < count; ++v)
            if (group[v] == g) oldToNew[v] = static_cast<std::uint32_t>(newToOld.size()), newToOld.push_back(v);
        if (g < kLodLevels) vertexCount[kLodLevels - 1 - g] = static_cast<std::uint32_t>(newToOld.size());
    }
    // Level 0 skins every vertex, as before LODs existed (a loader may keep a few no triangle uses).
    vertexCount[0] = static_cast<std::uint32_t>(count);

    std::vector<gpu::SkinVertex> vertices(count);
    for (std::size_t i = 0; i < count; ++i) vertices[i] = model.vertices[newToOld[i]];
    model.vertices = std::move(vertices);
    if (!model.uvs.empty()) {
        std::vector<glm::vec2> uvs(count);
        for (std::size_t i = 0; i < count; ++i) uvs[i] = model.uvs[newToOld[i]];
        model.uvs = std::move(uvs);
    }
    for (Triangles& level : levels)
        for (std::uint32_t& index : level) index = oldToNew[index];
    for (SkinnedModel::PropPart& prop : model.props)
        for (Triangles& level : prop.coarserLevels)
            for (std::uint32_t& index : level) index = oldToNew[index];
    return vertexCount;
}

// The triangles of the body: those not on a prop's joint (a prop is rigid on its own joint,
// model/attach_prop.h), in their authored order.
Triangles bodyTriangles(const SkinnedModel& model) {
    const std::vector<std::uint32_t>& propOfJoint = model.skeleton.propOfJoint;
    Triangles body;
    body.reserve(model.indices.size());
    for (std::size_t t = 0; t + 2 < model.indices.size(); t += 3) {
        const std::uint32_t joint = model.vertices[model.indices[t]].joints.x;
        if (joint < propOfJoint.size() && propOfJoint[joint] != 0u) continue;
        body.insert(body.end(), model.indices.begin() + static_cast<std::ptrdiff_t>(t),
                    model.indices.begin() + static_cast<std::ptrdiff_t>(t) + 3);
    }
    return body;
}

}  // namespace

std::size_t lodTriangleTarget(std::size_t fullTriangles, std::size_t level) {
    const double target = std::round(static_cast<double>(fullTriangles) * kLevelRatio[level]);
    return std::max<std::size_t>(1, static_cast<std::size_t>(target));
}

void buildLods(SkinnedModel& model) {
    model.lods.clear();
    std::array<Triangles, kLodLevels> levels;
    levels[0] = model.indices;
    // Only the body is simplified, at the paper's budgets of its own triangles; each prop draws its own
    // levels beside it (PropPart::coarserLevels), which use vertices of the prop's level above, so
    // every level's vertices still nest in the finer level's. Each body level is simplified from the
    // one above, not from the full mesh: a collapse only ever moves a vertex onto another of the
    // parent's, so the levels' vertex sets nest.
    const std::vector<std::uint32_t> jointRegions = bendRegions(model);
    Triangles body = bodyTriangles(model);
    const std::size_t bodyTriangleCount = body.size() / 3;
    for (std::size_t l = 1; l < kLodLevels; ++l) {
        body = simplifyLevel(model, jointRegions, body, lodTriangleTarget(bodyTriangleCount, l));
        levels[l] = body;
        for (const SkinnedModel::PropPart& prop : model.props)
            levels[l].insert(levels[l].end(), prop.coarserLevels[l - 1].begin(), prop.coarserLevels[l - 1].end());
    }
    const std::array<std::uint32_t, kLodLevels> vertexCount = reorderVertices(model, levels);
    model.indices = levels[0];
    // The full mesh keeps its authored triangle order (the picture is the same as without LODs); the
    // simplified levels come out of the simplifier in collapse order, so order them for the vertex cache.
    for (std::size_t l = 1; l < kLodLevels; ++l) {
        const Triangles authored = levels[l];
        meshopt_optimizeVertexCache(levels[l].data(), authored.data(), authored.size(), vertexCount[l]);
    }
    for (std::size_t l = 0; l < kLodLevels; ++l) model.lods.push_back({std::move(levels[l]), vertexCount[l]});
}

}  // namespace model
