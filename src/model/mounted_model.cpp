#include "model/mounted_model.h"

#include <algorithm>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/matrix_decompose.hpp>

#include "anim/local_to_model.h"
#include "gpu/error.h"
#include "model/procedural_models.h"
#include "model/riding_clip.h"

namespace model {
namespace {

std::vector<glm::mat4> restGlobals(const anim::Skeleton& s) {
    std::vector<glm::mat4> global(s.jointCount());
    anim::localToModel(s.parents, s.restPose, s.rootTransform, global);
    return global;
}

std::uint32_t findSaddle(const SkinnedModel& mount, const std::string& saddleJoint) {
    const std::vector<std::string>& names = mount.skeleton.jointNames;
    const auto it = std::find(names.begin(), names.end(), saddleJoint);
    if (it == names.end())
        throw gpu::Error(mount.name + ": no joint '" + saddleJoint + "' to seat a rider on (a mount needs one)");
    return static_cast<std::uint32_t>(it - names.begin());
}

// How high the rider's first root sits above the saddle: from the lowest vertex that joint carries
// most of (the seat of the trousers, for the soldier) up to the joint.
float seatHeight(const SkinnedModel& rider, std::uint32_t root, const glm::vec3& rootAtRest) {
    float lowest = std::numeric_limits<float>::max();
    for (const gpu::SkinVertex& v : rider.vertices)
        for (int k = 0; k < 4; ++k)
            if (v.joints[k] == root && v.weights[k] >= 0.5f) lowest = std::min(lowest, v.position.y);
    return lowest == std::numeric_limits<float>::max() ? 0.0f : rootAtRest.y - lowest;
}

anim::Transform asTransform(const glm::mat4& m) {
    anim::Transform t;
    glm::vec3 skew;
    glm::vec4 perspective;
    glm::decompose(m, t.scale, t.rotation, t.translation, skew, perspective);
    return t;
}

// The rider's joints after the mount's: names prefixed, roots under the saddle, and `placement` (the
// rider's model space into the mounted one) folded into the roots' rest and every inverse bind.
void appendRiderSkeleton(anim::Skeleton& out, const anim::Skeleton& rider, std::uint32_t saddle,
                         const glm::mat4& saddleAtRest, const glm::mat4& placement) {
    const auto offset = static_cast<std::int32_t>(out.jointCount());
    const glm::mat4 placementInverse = glm::inverse(placement);
    for (std::size_t j = 0; j < rider.jointCount(); ++j) {
        out.jointNames.push_back(kRiderJointPrefix + rider.jointNames[j]);
        const bool root = rider.parents[j] < 0;
        out.parents.push_back(root ? static_cast<std::int32_t>(saddle) : rider.parents[j] + offset);
        // A root's rest, seen from the saddle, puts it where the placement carries it at rest.
        out.restPose.push_back(root ? asTransform(glm::inverse(saddleAtRest) * placement * rider.rootTransform *
                                                  rider.restPose[j].matrix())
                                    : rider.restPose[j]);
        out.inverseBind.push_back(rider.inverseBind[j] * placementInverse);
    }
}

// The rider's props (a soldier's rifle, a flag) stay props of the pair, after the mount's: each
// character still chooses which it carries, and the pair's bounds leave them out as the rider's did.
// Their own coarser levels follow the rider's vertices, appended after the mount's (`vertexOffset`).
void appendRiderProps(SkinnedModel& out, const SkinnedModel& mount, const SkinnedModel& rider, std::uint32_t jointOffset,
                      std::uint32_t vertexOffset) {
    out.props = mount.props;
    if (mount.props.size() + rider.props.size() > MAX_PROPS)
        throw gpu::Error(mount.name + " and " + rider.name + ": " + std::to_string(mount.props.size() + rider.props.size()) +
                         " props together, more than a model carries (" + std::to_string(MAX_PROPS) + ")");
    const auto propShift = static_cast<std::uint32_t>(mount.props.size());
    for (SkinnedModel::PropPart prop : rider.props) {
        prop.joint += jointOffset;
        prop.attachedTo += jointOffset;
        for (std::vector<std::uint32_t>& level : prop.coarserLevels)
            for (std::uint32_t& index : level) index += vertexOffset;
        out.props.push_back(prop);
    }
    if (out.props.empty()) return;
    anim::Skeleton& s = out.skeleton;
    s.propOfJoint.resize(s.jointCount(), 0u);  // the mount's joints first (0 where it had none)
    for (std::size_t j = 0; j < rider.skeleton.propOfJoint.size(); ++j)
        if (rider.skeleton.propOfJoint[j] != 0) s.propOfJoint[jointOffset + j] = rider.skeleton.propOfJoint[j] + propShift;
}

// Materials and the one texture: the rider's materials follow the mount's.
void mergeMaterials(SkinnedModel& out, const SkinnedModel& mount, const SkinnedModel& rider,
                    std::vector<std::string>* notes) {
    if (mount.materialColors.size() + rider.materialColors.size() > MAX_MODEL_MATERIALS)
        throw gpu::Error(mount.name + " and " + rider.name + ": " +
                         std::to_string(mount.materialColors.size() + rider.materialColors.size()) +
                         " materials together, more than a model has (" + std::to_string(MAX_MODEL_MATERIALS) + ")");
    out.materialColors = mount.materialColors;
    out.materialColors.insert(out.materialColors.end(), rider.materialColors.begin(), rider.materialColors.end());
    const auto shift = static_cast<std::uint32_t>(mount.materialColors.size());
    const bool mountTexture = !mount.baseColorTexture.rgba.empty(), riderTexture = !rider.baseColorTexture.rgba.empty();
    out.texturedMaterials = mount.texturedMaterials;
    if (mountTexture) out.baseColorTexture = mount.baseColorTexture;
    if (riderTexture && !mountTexture) {
        out.baseColorTexture = rider.baseColorTexture;
        out.texturedMaterials = rider.texturedMaterials << shift;
    } else if (riderTexture && notes) {
        notes->push_back(rider.name + " on " + mount.name + ": both have a texture; the rider's is left out");
    }
    if (!mount.uvs.empty() || !rider.uvs.empty()) {
        out.uvs = mount.uvs;
        out.uvs.resize(mount.vertices.size(), glm::vec2(0.0f));
        if (rider.uvs.empty()) out.uvs.resize(mount.vertices.size() + rider.vertices.size(), glm::vec2(0.0f));
        else out.uvs.insert(out.uvs.end(), rider.uvs.begin(), rider.uvs.end());
    }
}

void appendRiderMesh(SkinnedModel& out, const SkinnedModel& rider, std::uint32_t jointOffset,
                     std::uint32_t materialOffset, const glm::mat4& placement) {
    const auto vertexOffset = static_cast<std::uint32_t>(out.vertices.size());
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(placement)));
    for (gpu::SkinVertex v : rider.vertices) {
        v.position = placement * glm::vec4(glm::vec3(v.position), 1.0f);
        v.normal = glm::vec4(glm::normalize(normalMatrix * glm::vec3(v.normal)), v.normal.w + static_cast<float>(materialOffset));
        // Unused slots keep pointing at joint 0, as every loader leaves them.
        for (int k = 0; k < 4; ++k)
            if (v.weights[k] != 0.0f) v.joints[k] += jointOffset;
        out.vertices.push_back(v);
    }
    for (std::uint32_t index : rider.indices) out.indices.push_back(index + vertexOffset);
}

}  // namespace

SkinnedModel mountRider(const SkinnedModel& mount, const SkinnedModel& rider, const std::string& saddleJoint,
                        std::string name, std::vector<std::string>* notes) {
    const std::uint32_t saddle = findSaddle(mount, saddleJoint);
    if (rider.skeleton.jointCount() == 0) throw gpu::Error(rider.name + ": a rider needs a skeleton");
    const std::vector<glm::mat4> mountRest = restGlobals(mount.skeleton);
    const std::vector<glm::mat4> riderRest = restGlobals(rider.skeleton);
    const auto riderRoot = static_cast<std::uint32_t>(
        std::find(rider.skeleton.parents.begin(), rider.skeleton.parents.end(), -1) - rider.skeleton.parents.begin());
    const glm::vec3 rootAtRest = riderRest[riderRoot][3];
    const glm::vec3 seat = glm::vec3(mountRest[saddle][3]) + glm::vec3(0.0f, seatHeight(rider, riderRoot, rootAtRest), 0.0f);
    const glm::mat4 placement = glm::translate(glm::mat4(1.0f), seat - rootAtRest);

    SkinnedModel out;
    out.name = std::move(name);
    out.skeleton = mount.skeleton;
    const auto jointOffset = static_cast<std::uint32_t>(mount.skeleton.jointCount());
    appendRiderSkeleton(out.skeleton, rider.skeleton, saddle, mountRest[saddle], placement);
    appendRiderProps(out, mount, rider, jointOffset, static_cast<std::uint32_t>(mount.vertices.size()));
    mergeMaterials(out, mount, rider, notes);
    out.vertices = mount.vertices;
    out.indices = mount.indices;
    appendRiderMesh(out, rider, jointOffset, static_cast<std::uint32_t>(mount.materialColors.size()), placement);
    computeBounds(out);
    out.footingHeight = mount.footingHeight > 0.0f ? mount.footingHeight : mount.height();

    const std::optional<RiderRig> rig = findRiderRig(out.skeleton, kRiderJointPrefix);
    if (!rig && notes)
        notes->push_back(rider.name + " on " + mount.name + ": the rider's joints are not named as the soldier's "
                         "(hips, thigh_l, ...): it rides in its rest pose");
    for (const anim::Clip& mountClip : mount.clips) {
        anim::Clip clip = mountClip;
        if (rig) {
            anim::Clip riding = bakeRidingClip(out, *rig, saddle, mountClip);
            for (anim::Channel& channel : riding.channels) clip.channels.push_back(std::move(channel));
        }
        out.clips.push_back(std::move(clip));
    }
    return out;
}

SkinnedModel makeCavalry(std::uint32_t seed) {
    return mountRider(makeHorse(seed), makeSoldier(seed), "saddle", "cavalry", nullptr);
}

}  // namespace model
