// crowdgpu::Prop and Model::withProps: rigid meshes on joints (model/attach_prop.h).
#include <cstring>

#include <glm/glm.hpp>

#include "api/api_data.h"
#include "crowd/pose_bounds.h"
#include "crowdgpu/model.hpp"
#include "model/attach_prop.h"
#include "model/gltf_prop.h"
#include "model/lod_builder.h"

namespace crowdgpu {
namespace {

Prop makeProp(model::PropMesh mesh) {
    return Prop(std::make_shared<const detail::PropData>(detail::PropData{std::move(mesh)}));
}

// Three row-major rows [R*s | t] as a column-major 4x4 matrix.
glm::mat4 offsetMatrix(const float rows[12]) {
    glm::mat4 m(1.0f);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) m[c][r] = rows[4 * r + c];
    return m;
}

}  // namespace

Prop::Prop(std::shared_ptr<const detail::PropData> data) : data_(std::move(data)) {}
Prop Prop::rifle() { return detail::translated([] { return makeProp(model::makeRifle()); }); }
Prop Prop::flag() { return detail::translated([] { return makeProp(model::makeFlag()); }); }

Prop Prop::fromGltf(const std::string& path, const std::string& assetRoot) {
    return detail::translated([&] {
        try {
            return makeProp(model::loadGltfProp(path, nullptr, assetRoot));
        } catch (const gpu::Error& error) {
            throw Error(ErrorCode::LoadFailed, error.what());
        }
    });
}

std::uint32_t Prop::lodTriangles(std::uint32_t lod) const {
    if (lod >= model::kLodLevels)
        throw Error(ErrorCode::InvalidArgument, name() + ": no level of detail " + std::to_string(lod));
    return static_cast<std::uint32_t>(data_->mesh.triangleCount(lod));
}
const std::string& Prop::name() const { return data_->mesh.name; }
std::uint32_t Prop::vertexCount() const { return static_cast<std::uint32_t>(data_->mesh.vertices.size()); }
std::uint32_t Prop::triangleCount() const { return static_cast<std::uint32_t>(data_->mesh.triangleCount()); }

Model Model::withProps(const std::vector<PropAttachment>& props) const {
    return detail::translated([&] {
        model::SkinnedModel carrying = data_->model;
        for (const PropAttachment& p : props) {
            try {
                model::attachProp(carrying, p.prop.data()->mesh, p.joint, offsetMatrix(p.offset), p.share);
            } catch (const gpu::Error& error) {
                throw Error(ErrorCode::InvalidArgument, error.what());
            }
        }
        // The mesh changed: its levels (which reorder the vertices) and its pose sphere are made again.
        model::buildLods(carrying);
        carrying.poseSphere = crowd::computePoseSphere(carrying);
        return Model(std::make_shared<const detail::ModelData>(detail::ModelData{std::move(carrying), data_->notes}));
    });
}

std::uint32_t Model::propCount() const { return static_cast<std::uint32_t>(data_->model.props.size()); }

const std::string& Model::propName(std::uint32_t prop) const {
    if (prop >= data_->model.props.size())
        throw Error(ErrorCode::InvalidArgument, name() + ": no prop " + std::to_string(prop) + " (it has " +
                                                    std::to_string(propCount()) + ")");
    return data_->model.props[prop].name;
}

std::uint32_t Model::propJoint(std::uint32_t prop) const {
    propName(prop);  // checks the index
    return data_->model.props[prop].joint;
}

}  // namespace crowdgpu
