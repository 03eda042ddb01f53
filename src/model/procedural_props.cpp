// The built-in props: a rifle and a flag, flat-shaded boxes, rigid on joint 0 of their own space, with
// coarser levels drawn over level 0's vertices.
#include <set>

#include "gpu/error.h"
#include "model/mesh_builder.h"
#include "model/prop_mesh.h"

namespace model {
namespace {

using Triangles = std::vector<std::uint32_t>;

// Boxes built on a scratch model (the mesh builder's), then taken as a prop; the coarser levels pick
// whole boxes, single faces and lofts between box ends out of the same vertices.
struct PropBuilder {
    SkinnedModel scratch;
    struct BoxPart {
        Box box;
        std::uint32_t firstVertex = 0, firstIndex = 0;
    };
    std::vector<BoxPart> boxes;

    explicit PropBuilder(std::string name, std::vector<glm::vec4> colours) {
        scratch.name = std::move(name);
        scratch.materialColors = std::move(colours);
    }
    std::size_t box(glm::vec3 center, glm::vec3 halfExtent, std::uint32_t material) {
        BoxPart part;
        part.box.center = center;
        part.box.halfExtent = halfExtent;
        part.box.material = material;
        part.box.skin = rigid(0);
        part.firstVertex = static_cast<std::uint32_t>(scratch.vertices.size());
        part.firstIndex = static_cast<std::uint32_t>(scratch.indices.size());
        addBox(scratch, part.box);
        boxes.push_back(part);
        return boxes.size() - 1;
    }

    Triangles wholeBox(std::size_t b) const {
        const auto first = scratch.indices.begin() + boxes[b].firstIndex;
        return Triangles(first, first + 36);
    }
    // The two triangles of box b's face whose outward normal is `normal` (an axis, ±1).
    Triangles face(std::size_t b, glm::vec3 normal) const {
        Triangles out;
        const auto first = scratch.indices.begin() + boxes[b].firstIndex;
        for (auto t = first; t != first + 36; t += 3)
            if (glm::vec3(scratch.vertices[*t].normal) == normal) out.insert(out.end(), t, t + 3);
        return out;
    }
    // The vertex of box b on its `normal` face at the corner whose offsets from the centre have these signs.
    std::uint32_t corner(std::size_t b, glm::vec3 normal, glm::vec3 signs) const {
        for (std::uint32_t v = boxes[b].firstVertex; v < boxes[b].firstVertex + 24; ++v) {
            const gpu::SkinVertex& vertex = scratch.vertices[v];
            const glm::vec3 offset = glm::vec3(vertex.position) - boxes[b].box.center;
            if (glm::vec3(vertex.normal) == normal && glm::all(glm::equal(glm::sign(offset), signs))) return v;
        }
        throw gpu::Error(scratch.name + ": no such box corner");  // a bug in this file, not in input
    }
    // A tube along z with four flat sides and no caps, from the back end (-z) of box `back` to the
    // front end (+z) of box `front`: each side joins the two boxes' corners on the same side, so it
    // carries their flat normals (the taper tilts it by a degree or two) and adds no vertex.
    Triangles loftAlongZ(std::size_t back, std::size_t front) const {
        Triangles out;
        for (const glm::vec3 n : {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, -1, 0)}) {
            // The two corners of the side across it: along y for an x side, along x for a y side.
            const glm::vec3 across = n.x != 0.0f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
            const glm::vec3 out1 = n + across, out2 = n - across;
            const std::uint32_t a = corner(back, n, out1 - glm::vec3(0, 0, 1)), b = corner(back, n, out2 - glm::vec3(0, 0, 1));
            const std::uint32_t c = corner(front, n, out2 + glm::vec3(0, 0, 1)), d = corner(front, n, out1 + glm::vec3(0, 0, 1));
            appendQuadFacing(out, {a, b, c, d}, n);
        }
        return out;
    }
    // Quad a-b-c-d (in order round it) as two triangles, wound counter-clockwise seen from `normal`.
    void appendQuadFacing(Triangles& out, std::array<std::uint32_t, 4> q, glm::vec3 normal) const {
        const glm::vec3 p0(scratch.vertices[q[0]].position), p1(scratch.vertices[q[1]].position),
            p2(scratch.vertices[q[2]].position);
        if (glm::dot(glm::cross(p1 - p0, p2 - p0), normal) < 0.0f) std::swap(q[1], q[3]);
        out.insert(out.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
    }

    PropMesh finish(std::array<Triangles, kLodLevels> levels) const {
        PropMesh prop = propFromModel(scratch);
        prop.levels = std::move(levels);
        checkPropMesh(prop, prop.name);
        return prop;
    }
};

Triangles joined(std::initializer_list<Triangles> parts) {
    Triangles out;
    for (const Triangles& part : parts) out.insert(out.end(), part.begin(), part.end());
    return out;
}

}  // namespace

PropMesh makeRifle() {
    enum : std::uint32_t { Metal, Wood };
    // The soldier's palette's metal and wood, so the rifle adds no material to it.
    PropBuilder rifle("rifle", {{0.025f, 0.025f, 0.03f, 1.0f}, {0.18f, 0.08f, 0.03f, 1.0f}});
    // Along +z from butt to muzzle, 0.95 m; the hand closes at the origin, under the receiver's front.
    const std::size_t stock = rifle.box({0.0f, 0.04f, -0.38f}, {0.02f, 0.045f, 0.12f}, Wood);
    rifle.box({0.0f, 0.05f, -0.12f}, {0.025f, 0.035f, 0.15f}, Metal);  // receiver
    const std::size_t magazine = rifle.box({0.0f, -0.03f, -0.07f}, {0.015f, 0.05f, 0.03f}, Metal);
    const std::size_t handguard = rifle.box({0.0f, 0.05f, 0.13f}, {0.022f, 0.028f, 0.11f}, Wood);
    const std::size_t barrel = rifle.box({0.0f, 0.05f, 0.34f}, {0.011f, 0.011f, 0.11f}, Metal);
    // A triangle shows one material (the stock and handguard are wood, the barrel metal), so the tube is
    // lofted between the two wooden parts. Level 1 (32 triangles): one tapered wooden tube from the butt
    // to the handguard's front, the magazine and the barrel. Level 2 (16): that tube and the barrel's
    // four sides (no caps), so the rifle still reaches from butt to muzzle.
    const Triangles wood = rifle.loftAlongZ(stock, handguard);
    const Triangles barrelSides = joined({rifle.face(barrel, {1, 0, 0}), rifle.face(barrel, {-1, 0, 0}),
                                          rifle.face(barrel, {0, 1, 0}), rifle.face(barrel, {0, -1, 0})});
    return rifle.finish({rifle.scratch.indices, joined({wood, rifle.wholeBox(magazine), rifle.wholeBox(barrel)}),
                         joined({wood, barrelSides})});
}

PropMesh makeFlag() {
    enum : std::uint32_t { Wood, Cloth, Metal };
    PropBuilder flag("flag", {{0.18f, 0.08f, 0.03f, 1.0f}, {0.45f, 0.03f, 0.02f, 1.0f}, {0.025f, 0.025f, 0.03f, 1.0f}});
    // A pole along +y held 0.4 m from its foot, 2.0 m long, the cloth at its top trailing towards -z.
    const std::size_t pole = flag.box({0.0f, 0.6f, 0.0f}, {0.012f, 1.0f, 0.012f}, Wood);
    const std::size_t cloth = flag.box({0.0f, 1.34f, -0.31f}, {0.005f, 0.2f, 0.3f}, Cloth);
    flag.box({0.0f, 1.62f, 0.0f}, {0.02f, 0.02f, 0.02f}, Metal);  // finial
    // Level 1 (24 triangles): the pole and the cloth, no finial. Level 2 (12): the pole's four sides and
    // the cloth as a flat quad, its two broad faces (1 cm apart: one seen from each side).
    return flag.finish({flag.scratch.indices, joined({flag.wholeBox(pole), flag.wholeBox(cloth)}),
                        joined({flag.face(pole, {1, 0, 0}), flag.face(pole, {-1, 0, 0}), flag.face(pole, {0, 0, 1}),
                                flag.face(pole, {0, 0, -1}), flag.face(cloth, {1, 0, 0}), flag.face(cloth, {-1, 0, 0})})});
}

PropMesh propFromModel(const SkinnedModel& model) {
    for (const gpu::SkinVertex& v : model.vertices)
        if (v.joints.x != 0u || v.weights.x != 1.0f)
            throw gpu::Error(model.name + ": a prop is rigid, but a vertex is skinned to more than its root");
    PropMesh prop{model.name, model.vertices, {}, model.materialColors};
    for (std::size_t l = 0; l < kLodLevels; ++l) prop.levels[l] = model.lods.size() == kLodLevels ? model.lods[l].indices : model.indices;
    return prop;
}

void checkPropMesh(const PropMesh& prop, const std::string& what) {
    if (prop.levels[0].empty()) throw gpu::Error(what + ": the prop has no triangles");
    for (const gpu::SkinVertex& v : prop.vertices)
        if (v.joints.x != 0u || v.weights.x != 1.0f) throw gpu::Error(what + ": a prop's vertex is not rigid on its root");
    std::set<std::uint32_t> above;
    for (std::size_t l = 0; l < kLodLevels; ++l) {
        const std::vector<std::uint32_t>& level = prop.levels[l];
        if (level.size() % 3 != 0) throw gpu::Error(what + ": level " + std::to_string(l) + " is not a triangle list");
        for (std::uint32_t index : level) {
            if (index >= prop.vertices.size()) throw gpu::Error(what + ": an index past its vertices");
            if (l > 0 && !above.contains(index))
                throw gpu::Error(what + ": level " + std::to_string(l) + " uses a vertex level " + std::to_string(l - 1) +
                                 " does not");
        }
        above = std::set<std::uint32_t>(level.begin(), level.end());
    }
}

}  // namespace model
