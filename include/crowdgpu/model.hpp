// crowdgpu: a skinned character model, Vulkan-free (link crowdgpu::core).
//
// A Model is a mesh with a skeleton, its clips, three levels of detail (built at load time with
// meshoptimizer) and a pose sphere that bounds every pose of every clip. Models are immutable and
// cheap to copy (shared). The built-in soldier and horse are procedural: no files needed.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace crowdgpu {

namespace detail { struct ModelData; struct PropData; }

// A rigid mesh a character carries on a joint (a rifle, a flag, a shield): drawn, culled, shadowed,
// given levels of detail and baked into impostors with its character, at no cost per prop per frame
// (docs/props.md). Immutable and cheap to copy.
class Prop {
public:
    // The built-in rifle (0.95 m along +z, muzzle forward, the grip at the origin) and flag (a 2 m pole
    // along +y from 0.4 m below the origin, where a hand holds it, its cloth at the top towards -z).
    // Each has levels of detail of its own: the model's level l draws the prop's level l.
    static Prop rifle();
    static Prop flag();
    // The first mesh (all its triangle primitives) of a glTF 2.0 file (.gltf or .glb) in its own space,
    // rigid: positions, normals and each primitive's base-colour factor; no skin needed, node transforms,
    // textures and animations not read. Named after the file's stem; its levels are made by
    // meshoptimizer as a model's are. External buffers must lie inside `assetRoot` (empty: the file's
    // folder). Throws Error(LoadFailed) with one line naming the file and the problem.
    static Prop fromGltf(const std::string& path, const std::string& assetRoot = {});

    const std::string& name() const;
    std::uint32_t vertexCount() const;    // of all its levels
    std::uint32_t triangleCount() const;  // of level 0, the full prop
    std::uint32_t lodTriangles(std::uint32_t lod) const;  // of a level (0..2); throws Error(InvalidArgument) past 2

    const std::shared_ptr<const detail::PropData>& data() const { return data_; }
    explicit Prop(std::shared_ptr<const detail::PropData> data);

private:
    std::shared_ptr<const detail::PropData> data_;
};

// A prop on a joint: its world transform is the joint's world transform times `offset`.
struct PropAttachment {
    Prop prop;
    std::string joint;  // the joint's name (Model::findJoint)
    // The prop's space to the joint's: three rows of a 3x4 matrix [R*s | t], row-major (as
    // Crowd::jointWorld writes), a rotation, a uniform scale and a translation in metres.
    float offset[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    float share = 1.0f;  // of the characters that carry it when they do not choose (Character::props)
};

class Model {
public:
    // The built-in soldier (about 1.8 m; clips walk, run, idle) and horse; `seed` varies their
    // proportions. The soldier carries a rifle and, one in eight, a flag (props, docs/props.md);
    // `props` false: neither (their cost, measured). Costs a few tens of milliseconds (mesh, clips and
    // their footsteps, LODs, pose sphere).
    static Model soldier(std::uint32_t seed = 1, bool props = true);
    static Model horse(std::uint32_t seed = 1);
    // A rider on a mount as one character (docs/cavalry.md): the mount's skeleton and mesh plus the
    // rider's, its root seated on the mount's `saddleJoint` (the built-in horse's "saddle"), so the
    // pair is culled, skinned, shadowed and moved as one and cannot drift apart. Its clips are the
    // mount's ("walk", "gallop", ...), each joined with a riding clip of the same duration and phase
    // for a rider whose joints are named as the soldier's (else the rider keeps its rest pose, with a
    // note). The rider's joints are named "rider_" + their name. Throws Error(InvalidArgument) naming
    // the mount and the joint when the mount has no such joint, and when the two have more than 16
    // materials together. Costs what loading a model does (LODs, pose sphere).
    static Model mounted(const Model& mount, const Model& rider, const std::string& saddleJoint = "saddle");
    // The built-in cavalryman: the soldier on the horse, named "cavalry".
    static Model cavalry(std::uint32_t seed = 1);
    // A skinned glTF 2.0 character (.gltf or .glb). External buffers and images must lie inside
    // `assetRoot` (empty: the file's own folder). Throws Error(LoadFailed) naming the file and the
    // problem. Cost: the file's size, plus sampling every clip to bound its poses.
    static Model fromGltf(const std::string& path, const std::string& assetRoot = {});

    const std::string& name() const;
    // This model carrying `props` besides its own (appended as props propCount(), ...): each prop is a
    // rigid part of the mesh on a joint of its own, named after it and child of the attachment's joint,
    // so jointCount() grows by one a prop. Levels of detail and the pose sphere are built again
    // (milliseconds). Throws Error(InvalidArgument) naming the model and the joint when it has no such
    // joint, and for an offset that is not a rotation with a uniform scale, a share outside [0, 1],
    // more than 16 props or 16 materials.
    Model withProps(const std::vector<PropAttachment>& props) const;
    // Its props (the soldier's: 0 "rifle" in the right hand, 1 "flag" in the left, carried by one in eight).
    std::uint32_t propCount() const;
    const std::string& propName(std::uint32_t prop) const;  // throws Error(InvalidArgument) past propCount()
    std::uint32_t propJoint(std::uint32_t prop) const;      // the prop's own joint (Crowd::jointWorld)
    std::uint32_t jointCount() const;
    std::uint32_t vertexCount() const;
    std::uint32_t triangleCount() const;
    float height() const;  // metres (glTF units), rest pose, props left out
    std::uint32_t lodCount() const;
    std::uint32_t lodTriangles(std::uint32_t lod) const;
    std::uint32_t lodVertices(std::uint32_t lod) const;
    // The sphere that bounds every pose of every clip (what culling and LOD test), in model space.
    void poseSphere(float center[3], float& radius) const;
    std::uint32_t clipCount() const;
    const std::string& clipName(std::uint32_t clip) const;
    float clipDuration(std::uint32_t clip) const;  // seconds
    // The clip of this name, or -1.
    std::int32_t findClip(const std::string& name) const;
    // The clip a character plays when none is named: "walk" when the model has one, else the first.
    std::uint32_t defaultClip() const;
    // A clip's animation events (what Crowd::events reports): named moments of its cycle, in time
    // order. The built-in models' walking clips carry a "footstep" for each foot's touchdown, its
    // joint that foot (the soldier's "foot_l", "foot_r"; the horse's "front_pastern_l", ...). A glTF
    // animation's come from its extras: "extras": {"events": [{"name": "shot", "time": 0.4,
    // "joint": "hand_r"}, ...]}, times in seconds within [0, the clip's duration], the joint optional
    // (docs/events.md). Throw Error(InvalidArgument) for a clip or event that does not exist. Cost:
    // an index.
    std::uint32_t eventCount(std::uint32_t clip) const;
    const std::string& eventName(std::uint32_t clip, std::uint32_t event) const;
    float eventTime(std::uint32_t clip, std::uint32_t event) const;  // seconds into the cycle
    // The joint where the event happens (a footstep's foot), or -1 when it names none.
    std::int32_t eventJoint(std::uint32_t clip, std::uint32_t event) const;
    // The joint of this name (glTF: its node's name; the soldier's "hand_r", "foot_l", ...), or -1.
    // Cost: a scan of the joint names.
    std::int32_t findJoint(const std::string& name) const;
    // Joint `joint`'s name; throws Error(InvalidArgument) past jointCount().
    const std::string& jointName(std::uint32_t joint) const;

    // The full-detail mesh's triangles: three vertex indices each, into pose()'s vertices.
    const std::vector<std::uint32_t>& indices() const;
    // One character's skinned vertices at `time` seconds into `clip`, standing at the origin: the
    // model's own space (for glTF, its scene's world space). A clip past the last gives the rest pose.
    // Computed on the CPU in double precision, one vertex at a time (the GPU methods' reference):
    // for exporting a pose, picking or physics, not for every character every frame.
    struct PosedVertex {
        double position[3];
        double normal[3];  // unit length
    };
    std::vector<PosedVertex> pose(std::uint32_t clip, float time) const;
    // What loading left out or changed (a glTF feature the library does not use), one line each.
    const std::vector<std::string>& notes() const;

    const std::shared_ptr<const detail::ModelData>& data() const { return data_; }
    explicit Model(std::shared_ptr<const detail::ModelData> data);

private:
    std::shared_ptr<const detail::ModelData> data_;
};

}  // namespace crowdgpu
