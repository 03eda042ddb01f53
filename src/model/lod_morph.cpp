#include "model/lod_morph.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace model {
namespace {

using Triangles = std::vector<std::uint32_t>;

// How many edges the search around a vertex walks at most before it gives up on the surface around
// it and takes every coarser triangle of its part.
constexpr std::uint32_t kMaxRings = 16;

// Vertices at one position are one for the search: a seam's copies (normals, uvs, materials) join the
// charts they separate. welded[v] is the first vertex at v's position.
std::vector<std::uint32_t> weldByPosition(const std::vector<gpu::SkinVertex>& vertices) {
    std::vector<std::uint32_t> order(vertices.size());
    std::iota(order.begin(), order.end(), 0u);
    auto key = [&](std::uint32_t v) {
        const glm::vec4& p = vertices[v].position;
        return std::array<float, 3>{p.x, p.y, p.z};
    };
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
    std::vector<std::uint32_t> welded(vertices.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        welded[order[i]] = i > 0 && key(order[i]) == key(order[i - 1]) ? welded[order[i - 1]] : order[i];
    return welded;
}

// The part a vertex belongs to: 0 the body, k + 1 prop k (skeleton.propOfJoint of its first joint, as
// the level builder tells them apart).
std::uint32_t partOf(const SkinnedModel& model, std::uint32_t v) {
    const std::uint32_t joint = model.vertices[v].joints.x;
    return joint < model.skeleton.propOfJoint.size() ? model.skeleton.propOfJoint[joint] : 0u;
}

// The point of triangle (a, b, c) nearest p, as barycentric weights of b and c (Ericson, Real-Time
// Collision Detection, 5.1.5), and its squared distance.
struct Nearest {
    double distance2 = std::numeric_limits<double>::max();
    glm::dvec2 weights{0.0};
};

Nearest nearestOnTriangle(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    glm::dvec2 w{0.0};  // weights of b and c
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
    if (d1 <= 0.0 && d2 <= 0.0) {
        w = {0.0, 0.0};  // vertex a
    } else if (d3 >= 0.0 && d4 <= d3) {
        w = {1.0, 0.0};  // vertex b
    } else if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        w = {d1 / (d1 - d3), 0.0};  // edge ab
    } else if (d6 >= 0.0 && d5 <= d6) {
        w = {0.0, 1.0};  // vertex c
    } else if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        w = {0.0, d2 / (d2 - d6)};  // edge ac
    } else if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
        const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        w = {1.0 - t, t};  // edge bc
    } else {
        const double denominator = 1.0 / (va + vb + vc);
        w = {vb * denominator, vc * denominator};  // inside
    }
    const glm::dvec3 q = a + w.x * ab + w.y * ac;
    return {glm::dot(p - q, p - q), w};
}

glm::dvec3 bindPosition(const SkinnedModel& model, std::uint32_t v) { return glm::dvec3(model.vertices[v].position); }

// The search of one level pair: level `fine`'s surface as a graph of welded vertices, and the
// triangles of the coarser level around each welded vertex.
class MorphSearch {
public:
    MorphSearch(const SkinnedModel& model, const std::vector<std::uint32_t>& welded, const Triangles& fine,
                const Triangles& coarse)
        : model_(model), welded_(welded), coarse_(coarse), neighbours_(model.vertices.size()),
          around_(model.vertices.size()), seen_(model.vertices.size(), 0u) {
        for (std::size_t t = 0; t + 2 < fine.size(); t += 3)
            for (int i = 0; i < 3; ++i) {
                const std::uint32_t a = welded[fine[t + i]], b = welded[fine[t + (i + 1) % 3]];
                neighbours_[a].push_back(b), neighbours_[b].push_back(a);
            }
        for (std::vector<std::uint32_t>& n : neighbours_) {
            std::sort(n.begin(), n.end());
            n.erase(std::unique(n.begin(), n.end()), n.end());
        }
        for (std::uint32_t t = 0; t + 2 < coarse.size(); t += 3)
            for (int i = 0; i < 3; ++i) around_[welded[coarse[t + i]]].push_back(t / 3);
        for (std::vector<std::uint32_t>& a : around_) a.erase(std::unique(a.begin(), a.end()), a.end());
    }

    LodMorphTarget targetOf(std::uint32_t v) {
        std::vector<std::uint32_t> candidates = nearbyTriangles(v);
        const std::uint32_t part = partOf(model_, v);
        std::erase_if(candidates, [&](std::uint32_t t) { return partOf(model_, coarse_[3 * t]) != part; });
        if (candidates.empty())  // a part the search did not reach: all of it
            for (std::uint32_t t = 0; 3 * t + 2 < coarse_.size(); ++t)
                if (partOf(model_, coarse_[3 * t]) == part) candidates.push_back(t);
        LodMorphTarget target{{v, v, v}, glm::vec2(0.0f)};
        Nearest best;
        const glm::dvec3 p = bindPosition(model_, v);
        for (std::uint32_t t : candidates) {  // ascending: ties go to the first triangle
            const std::uint32_t* c = &coarse_[3 * t];
            const Nearest n = nearestOnTriangle(p, bindPosition(model_, c[0]), bindPosition(model_, c[1]),
                                                bindPosition(model_, c[2]));
            if (n.distance2 < best.distance2) {
                best = n;
                target = {{c[0], c[1], c[2]}, glm::vec2(n.weights)};
            }
        }
        return target;
    }

private:
    // The coarser triangles around the coarser vertices the fewest edges away from v, and one edge
    // further (a vertex between two of them may lie nearer a triangle of the second ring), sorted.
    std::vector<std::uint32_t> nearbyTriangles(std::uint32_t v) {
        ++stamp_;
        std::vector<std::uint32_t> ring = {welded_[v]}, triangles;
        seen_[welded_[v]] = stamp_;
        std::uint32_t lastDepth = kMaxRings;
        for (std::uint32_t depth = 0; depth <= lastDepth && !ring.empty(); ++depth) {
            for (std::uint32_t w : ring) triangles.insert(triangles.end(), around_[w].begin(), around_[w].end());
            if (!triangles.empty() && lastDepth == kMaxRings) lastDepth = std::min(depth + 1, kMaxRings);
            std::vector<std::uint32_t> next;
            for (std::uint32_t w : ring)
                for (std::uint32_t n : neighbours_[w])
                    if (seen_[n] != stamp_) seen_[n] = stamp_, next.push_back(n);
            ring = std::move(next);
        }
        std::sort(triangles.begin(), triangles.end());
        triangles.erase(std::unique(triangles.begin(), triangles.end()), triangles.end());
        return triangles;
    }

    const SkinnedModel& model_;
    const std::vector<std::uint32_t>& welded_;
    const Triangles& coarse_;
    std::vector<std::vector<std::uint32_t>> neighbours_;  // per welded vertex, on the finer level
    std::vector<std::vector<std::uint32_t>> around_;      // per welded vertex, coarser triangles at it
    std::vector<std::uint32_t> seen_;
    std::uint32_t stamp_ = 0;
};

}  // namespace

std::vector<LodMorphTarget> lodMorphTargets(const SkinnedModel& model, const std::vector<SkinnedModel::Lod>& lods) {
    const auto count = static_cast<std::uint32_t>(model.vertices.size());
    std::vector<LodMorphTarget> targets(count);
    for (std::uint32_t v = 0; v < count; ++v) targets[v] = {{v, v, v}, glm::vec2(0.0f)};
    const std::vector<std::uint32_t> welded = weldByPosition(model.vertices);
    for (std::size_t l = 0; l + 1 < lods.size(); ++l) {
        const std::uint32_t first = lods[l + 1].vertexCount, end = std::min(lods[l].vertexCount, count);
        if (first >= end || lods[l + 1].indices.empty()) continue;
        std::vector<bool> used(count, false);
        for (std::uint32_t index : lods[l].indices) used[index] = true;
        MorphSearch search(model, welded, lods[l].indices, lods[l + 1].indices);
        for (std::uint32_t v = first; v < end; ++v)
            if (used[v]) targets[v] = search.targetOf(v);
    }
    return targets;
}

glm::uvec4 packLodMorphTarget(const LodMorphTarget& target) {
    auto unorm16 = [](float x) { return static_cast<std::uint32_t>(std::lround(std::clamp(x, 0.0f, 1.0f) * 65535.0f)); };
    return glm::uvec4(target.corners[0], target.corners[1], target.corners[2],
                      unorm16(target.weights.x) | (unorm16(target.weights.y) << 16));
}

}  // namespace model
