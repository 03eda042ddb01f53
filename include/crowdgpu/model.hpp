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

namespace detail { struct ModelData; }

class Model {
public:
    // The built-in soldier (about 1.8 m; clips walk, run, idle, wave, ...) and horse; `seed` varies
    // their proportions. Costs a few tens of milliseconds (mesh, clips and their footsteps, LODs,
    // pose sphere).
    static Model soldier(std::uint32_t seed = 1);
    static Model horse(std::uint32_t seed = 1);
    // A skinned glTF 2.0 character (.gltf or .glb). External buffers and images must lie inside
    // `assetRoot` (empty: the file's own folder). Throws Error(LoadFailed) naming the file and the
    // problem. Cost: the file's size, plus sampling every clip to bound its poses.
    static Model fromGltf(const std::string& path, const std::string& assetRoot = {});

    const std::string& name() const;
    std::uint32_t jointCount() const;
    std::uint32_t vertexCount() const;
    std::uint32_t triangleCount() const;
    float height() const;  // metres (glTF units), rest pose
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
