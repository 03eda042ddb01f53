// The built-in props: a rifle and a flag, flat-shaded boxes, rigid on joint 0 of their own space.
#include "gpu/error.h"
#include "model/mesh_builder.h"
#include "model/prop_mesh.h"

namespace model {
namespace {

// Boxes built on a scratch model (the mesh builder's), then taken as a prop.
struct PropBuilder {
    SkinnedModel scratch;
    explicit PropBuilder(std::string name, std::vector<glm::vec4> colours) {
        scratch.name = std::move(name);
        scratch.materialColors = std::move(colours);
    }
    void box(glm::vec3 center, glm::vec3 halfExtent, std::uint32_t material) {
        Box b;
        b.center = center;
        b.halfExtent = halfExtent;
        b.material = material;
        b.skin = rigid(0);
        addBox(scratch, b);
    }
};

}  // namespace

PropMesh makeRifle() {
    enum : std::uint32_t { Metal, Wood };
    // The soldier's palette's metal and wood, so the rifle adds no material to it.
    PropBuilder rifle("rifle", {{0.025f, 0.025f, 0.03f, 1.0f}, {0.18f, 0.08f, 0.03f, 1.0f}});
    // Along +z from butt to muzzle, 0.95 m; the hand closes at the origin, under the receiver's front.
    rifle.box({0.0f, 0.04f, -0.38f}, {0.02f, 0.045f, 0.12f}, Wood);     // stock
    rifle.box({0.0f, 0.05f, -0.12f}, {0.025f, 0.035f, 0.15f}, Metal);   // receiver
    rifle.box({0.0f, -0.03f, -0.07f}, {0.015f, 0.05f, 0.03f}, Metal);   // magazine
    rifle.box({0.0f, 0.05f, 0.13f}, {0.022f, 0.028f, 0.11f}, Wood);     // handguard
    rifle.box({0.0f, 0.05f, 0.34f}, {0.011f, 0.011f, 0.11f}, Metal);    // barrel
    return propFromModel(rifle.scratch);
}

PropMesh makeFlag() {
    enum : std::uint32_t { Wood, Cloth, Metal };
    PropBuilder flag("flag", {{0.18f, 0.08f, 0.03f, 1.0f}, {0.45f, 0.03f, 0.02f, 1.0f}, {0.025f, 0.025f, 0.03f, 1.0f}});
    // A pole along +y held 0.4 m from its foot, 2.0 m long, the cloth at its top trailing towards -z.
    flag.box({0.0f, 0.6f, 0.0f}, {0.012f, 1.0f, 0.012f}, Wood);        // pole
    flag.box({0.0f, 1.34f, -0.31f}, {0.005f, 0.2f, 0.3f}, Cloth);      // cloth
    flag.box({0.0f, 1.62f, 0.0f}, {0.02f, 0.02f, 0.02f}, Metal);       // finial
    return propFromModel(flag.scratch);
}

PropMesh propFromModel(const SkinnedModel& model) {
    for (const gpu::SkinVertex& v : model.vertices)
        if (v.joints.x != 0u || v.weights.x != 1.0f)
            throw gpu::Error(model.name + ": a prop is rigid, but a vertex is skinned to more than its root");
    return {model.name, model.vertices, model.indices, model.materialColors};
}

}  // namespace model
