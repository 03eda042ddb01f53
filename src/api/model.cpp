// crowdgpu::Model: the built-in and glTF characters, with their levels of detail and pose sphere.
#include "crowdgpu/model.hpp"

#include "api/api_data.h"
#include "crowd/pose_bounds.h"
#include "model/gltf_loader.h"
#include "model/lod_builder.h"
#include "model/mounted_model.h"
#include "model/procedural_models.h"
#include "skin/cpu_skinning.h"

namespace crowdgpu {
namespace {

// What every model gets before a crowd uses it: levels of detail (which reorder its vertices) and
// the sphere that bounds every pose (culling).
Model finish(model::SkinnedModel model, std::vector<std::string> notes) {
    model::buildLods(model);
    model.poseSphere = crowd::computePoseSphere(model);
    return Model(std::make_shared<const detail::ModelData>(detail::ModelData{std::move(model), std::move(notes)}));
}

}  // namespace

Model::Model(std::shared_ptr<const detail::ModelData> data) : data_(std::move(data)) {}

Model Model::soldier(std::uint32_t seed, bool props) {
    return detail::translated([&] { return finish(model::makeSoldier(seed, props), {}); });
}

Model Model::horse(std::uint32_t seed) {
    return detail::translated([&] { return finish(model::makeHorse(seed), {}); });
}

Model Model::mounted(const Model& mount, const Model& rider, const std::string& saddleJoint) {
    return detail::translated([&] {
        std::vector<std::string> notes;
        model::SkinnedModel pair = model::mountRider(mount.data()->model, rider.data()->model, saddleJoint,
                                                     rider.name() + " on " + mount.name(), &notes);
        return finish(std::move(pair), std::move(notes));
    });
}

Model Model::cavalry(std::uint32_t seed) {
    return detail::translated([&] {
        // The rider and mount before their levels of detail: finish() builds the pair's own.
        return finish(model::makeCavalry(seed), {});
    });
}

Model Model::fromGltf(const std::string& path, const std::string& assetRoot) {
    return detail::translated([&] {
        std::vector<std::string> notes;
        model::SkinnedModel loaded;
        try {
            loaded = model::loadGltf(path, &notes, assetRoot);
        } catch (const gpu::Error& error) {
            throw Error(ErrorCode::LoadFailed, error.what());
        }
        return finish(std::move(loaded), std::move(notes));
    });
}

const std::string& Model::name() const { return data_->model.name; }
std::uint32_t Model::jointCount() const { return static_cast<std::uint32_t>(data_->model.skeleton.jointCount()); }
std::uint32_t Model::vertexCount() const { return static_cast<std::uint32_t>(data_->model.vertices.size()); }
std::uint32_t Model::triangleCount() const { return static_cast<std::uint32_t>(data_->model.triangleCount()); }
float Model::height() const { return data_->model.height(); }
std::uint32_t Model::lodCount() const { return static_cast<std::uint32_t>(data_->model.lods.size()); }

std::uint32_t Model::lodTriangles(std::uint32_t lod) const {
    if (lod >= data_->model.lods.size())
        throw Error(ErrorCode::InvalidArgument, name() + ": no level of detail " + std::to_string(lod));
    return static_cast<std::uint32_t>(data_->model.lods[lod].indices.size() / 3);
}

std::uint32_t Model::lodVertices(std::uint32_t lod) const {
    lodTriangles(lod);  // checks the index
    return data_->model.lods[lod].vertexCount;
}

void Model::poseSphere(float center[3], float& radius) const {
    const glm::vec4& sphere = data_->model.poseSphere;
    center[0] = sphere.x, center[1] = sphere.y, center[2] = sphere.z;
    radius = sphere.w;
}

std::uint32_t Model::clipCount() const { return static_cast<std::uint32_t>(data_->model.clips.size()); }

const std::string& Model::clipName(std::uint32_t clip) const {
    if (clip >= data_->model.clips.size())
        throw Error(ErrorCode::InvalidArgument, name() + ": no clip " + std::to_string(clip));
    return data_->model.clips[clip].name;
}

float Model::clipDuration(std::uint32_t clip) const {
    clipName(clip);  // checks the index
    return data_->model.clips[clip].duration;
}

std::int32_t Model::findClip(const std::string& clipName) const { return data_->model.findClip(clipName); }
std::uint32_t Model::eventCount(std::uint32_t clip) const {
    clipName(clip);  // checks the index
    return static_cast<std::uint32_t>(data_->model.clips[clip].events.size());
}

const std::string& Model::eventName(std::uint32_t clip, std::uint32_t event) const {
    if (event >= eventCount(clip))
        throw Error(ErrorCode::InvalidArgument, name() + ": clip '" + clipName(clip) + "' has no event " + std::to_string(event));
    return data_->model.clips[clip].events[event].name;
}

float Model::eventTime(std::uint32_t clip, std::uint32_t event) const {
    eventName(clip, event);  // checks the indices
    return data_->model.clips[clip].events[event].time;
}

std::int32_t Model::eventJoint(std::uint32_t clip, std::uint32_t event) const {
    eventName(clip, event);  // checks the indices
    return data_->model.clips[clip].events[event].joint;
}

std::int32_t Model::findJoint(const std::string& jointName) const {
    const std::vector<std::string>& names = data_->model.skeleton.jointNames;
    for (std::size_t j = 0; j < names.size(); ++j)
        if (names[j] == jointName) return static_cast<std::int32_t>(j);
    return -1;
}

const std::string& Model::jointName(std::uint32_t joint) const {
    if (joint >= data_->model.skeleton.jointNames.size())
        throw Error(ErrorCode::InvalidArgument, name() + ": no joint " + std::to_string(joint) + " (it has " +
                                                    std::to_string(jointCount()) + ")");
    return data_->model.skeleton.jointNames[joint];
}

const std::vector<std::string>& Model::notes() const { return data_->notes; }
std::uint32_t Model::defaultClip() const { return crowd::defaultClip(data_->model); }
const std::vector<std::uint32_t>& Model::indices() const { return data_->model.indices; }

std::vector<Model::PosedVertex> Model::pose(std::uint32_t clip, float time) const {
    return detail::translated([&] {
        std::vector<PosedVertex> result;
        result.reserve(data_->model.vertices.size());
        for (const skin::CpuSkinnedVertex& v : skin::poseOnCpu(data_->model, clip, time))
            result.push_back({{v.position.x, v.position.y, v.position.z}, {v.normal.x, v.normal.y, v.normal.z}});
        return result;
    });
}

}  // namespace crowdgpu
