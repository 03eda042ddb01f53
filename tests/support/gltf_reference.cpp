#include "support/gltf_reference.h"

#include <cstring>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace test {
namespace {

// Accessor elements as doubles, components per element flattened (valid files only).
std::vector<double> readAccessor(const tinygltf::Model& model, int index) {
    const tinygltf::Accessor& a = model.accessors.at(static_cast<std::size_t>(index));
    const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
    const int size = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
    const tinygltf::BufferView& view = model.bufferViews.at(static_cast<std::size_t>(a.bufferView));
    const std::size_t stride = view.byteStride ? view.byteStride : static_cast<std::size_t>(components * size);
    const unsigned char* base =
        model.buffers.at(static_cast<std::size_t>(view.buffer)).data.data() + view.byteOffset + a.byteOffset;
    std::vector<double> out;
    for (std::size_t e = 0; e < a.count; ++e) {
        for (int c = 0; c < components; ++c) {
            const unsigned char* p = base + e * stride + static_cast<std::size_t>(c * size);
            double v = 0.0;
            switch (a.componentType) {
                case TINYGLTF_COMPONENT_TYPE_FLOAT: {
                    float f;
                    std::memcpy(&f, p, 4);
                    v = f;
                    break;
                }
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                    v = *p;
                    if (a.normalized) v /= 255.0;
                    break;
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                    std::uint16_t s;
                    std::memcpy(&s, p, 2);
                    v = s;
                    if (a.normalized) v /= 65535.0;
                    break;
                }
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
                    std::uint32_t u;
                    std::memcpy(&u, p, 4);
                    v = u;
                    break;
                }
                default: throw std::runtime_error("reference: unsupported component type");
            }
            out.push_back(v);
        }
    }
    return out;
}

struct Trs {
    glm::dvec3 t{0.0};
    glm::dquat r{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 s{1.0};
    bool isMatrix = false;
    glm::dmat4 m{1.0};
    glm::dmat4 matrix() const {
        if (isMatrix) return m;
        return glm::translate(glm::dmat4(1.0), t) * glm::mat4_cast(r) * glm::scale(glm::dmat4(1.0), s);
    }
};

Trs restOf(const tinygltf::Node& node) {
    Trs trs;
    if (node.matrix.size() == 16) {
        trs.isMatrix = true;
        trs.m = glm::make_mat4(node.matrix.data());
        return trs;
    }
    if (node.translation.size() == 3) trs.t = glm::make_vec3(node.translation.data());
    if (node.scale.size() == 3) trs.s = glm::make_vec3(node.scale.data());
    if (node.rotation.size() == 4)
        trs.r = glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    return trs;
}

// Samples one channel at `time` (clamped to its keys), as the glTF specification's appendix defines.
std::vector<double> sample(const std::vector<double>& times, const std::vector<double>& values, int width,
                           const std::string& interpolation, bool rotation, double time) {
    const bool cubic = interpolation == "CUBICSPLINE";
    auto value = [&](std::size_t key, int part) {  // part: 0 in-tangent, 1 value, 2 out-tangent
        const std::size_t index = cubic ? key * 3 + static_cast<std::size_t>(part) : key;
        return std::vector<double>(values.begin() + static_cast<std::ptrdiff_t>(index * width),
                                   values.begin() + static_cast<std::ptrdiff_t>((index + 1) * width));
    };
    if (time <= times.front()) return value(0, 1);
    if (time >= times.back()) return value(times.size() - 1, 1);
    std::size_t k = 0;
    while (times[k + 1] <= time) ++k;
    const double dt = times[k + 1] - times[k], u = (time - times[k]) / dt;
    if (interpolation == "STEP") return value(k, 1);
    std::vector<double> out(static_cast<std::size_t>(width));
    if (cubic) {
        const auto p0 = value(k, 1), m0 = value(k, 2), p1 = value(k + 1, 1), m1 = value(k + 1, 0);
        const double u2 = u * u, u3 = u2 * u;
        for (std::size_t i = 0; i < out.size(); ++i)
            out[i] = (2 * u3 - 3 * u2 + 1) * p0[i] + (u3 - 2 * u2 + u) * dt * m0[i] + (-2 * u3 + 3 * u2) * p1[i] +
                     (u3 - u2) * dt * m1[i];
    } else if (rotation) {
        const auto a = value(k, 1), b = value(k + 1, 1);
        const glm::dquat qa(a[3], a[0], a[1], a[2]), qb(b[3], b[0], b[1], b[2]);
        const glm::dquat q = glm::slerp(qa, glm::dot(qa, qb) < 0.0 ? -qb : qb, u);
        out = {q.x, q.y, q.z, q.w};
    } else {
        const auto a = value(k, 1), b = value(k + 1, 1);
        for (std::size_t i = 0; i < out.size(); ++i) out[i] = a[i] + (b[i] - a[i]) * u;
    }
    return out;
}

}  // namespace

tinygltf::Model parseWithTinygltf(const std::filesystem::path& path) {
    tinygltf::TinyGLTF parser;
    tinygltf::Model model;
    std::string error, warning;
    const bool binary = path.extension() == ".glb";
    const bool ok = binary ? parser.LoadBinaryFromFile(&model, &error, &warning, path.string())
                           : parser.LoadASCIIFromFile(&model, &error, &warning, path.string());
    if (!ok) throw std::runtime_error("tinygltf: " + error);
    return model;
}

std::vector<glm::dvec3> referenceSkinnedPositions(const tinygltf::Model& model, int animation, double time) {
    std::vector<Trs> local;
    for (const tinygltf::Node& node : model.nodes) local.push_back(restOf(node));
    if (animation >= 0) {
        const tinygltf::Animation& a = model.animations.at(static_cast<std::size_t>(animation));
        for (const tinygltf::AnimationChannel& channel : a.channels) {
            const tinygltf::AnimationSampler& s = a.samplers.at(static_cast<std::size_t>(channel.sampler));
            const bool rotation = channel.target_path == "rotation";
            if (!rotation && channel.target_path != "translation" && channel.target_path != "scale") continue;
            std::vector<double> values = readAccessor(model, s.output);
            if (rotation &&
                model.accessors[static_cast<std::size_t>(s.output)].componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
                throw std::runtime_error("reference: quantized rotations not supported");
            const std::vector<double> v =
                sample(readAccessor(model, s.input), values, rotation ? 4 : 3, s.interpolation, rotation, time);
            Trs& trs = local.at(static_cast<std::size_t>(channel.target_node));
            if (rotation)
                trs.r = glm::normalize(glm::dquat(v[3], v[0], v[1], v[2]));
            else if (channel.target_path == "translation")
                trs.t = {v[0], v[1], v[2]};
            else
                trs.s = {v[0], v[1], v[2]};
        }
    }
    std::vector<int> parent(model.nodes.size(), -1);
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
        for (const int c : model.nodes[n].children) parent.at(static_cast<std::size_t>(c)) = static_cast<int>(n);
    auto global = [&](int node) {
        glm::dmat4 m(1.0);
        for (int n = node; n != -1; n = parent[static_cast<std::size_t>(n)])
            m = local[static_cast<std::size_t>(n)].matrix() * m;
        return m;
    };

    int meshNode = -1;
    for (std::size_t n = 0; n < model.nodes.size() && meshNode < 0; ++n)
        if (model.nodes[n].mesh >= 0 && model.nodes[n].skin >= 0) meshNode = static_cast<int>(n);
    if (meshNode < 0) throw std::runtime_error("reference: no skinned mesh");
    const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(meshNode)];
    const tinygltf::Skin& skin = model.skins.at(static_cast<std::size_t>(node.skin));
    std::vector<glm::dmat4> jointMatrix;
    const std::vector<double> ibm =
        skin.inverseBindMatrices >= 0 ? readAccessor(model, skin.inverseBindMatrices) : std::vector<double>();
    for (std::size_t k = 0; k < skin.joints.size(); ++k)
        jointMatrix.push_back(global(skin.joints[k]) * (ibm.empty() ? glm::dmat4(1.0) : glm::make_mat4(&ibm[k * 16])));

    std::vector<glm::dvec3> out;
    for (const tinygltf::Primitive& primitive : model.meshes.at(static_cast<std::size_t>(node.mesh)).primitives) {
        const std::vector<double> positions = readAccessor(model, primitive.attributes.at("POSITION"));
        std::vector<std::vector<double>> joints, weights;
        for (int set = 0; primitive.attributes.count("JOINTS_" + std::to_string(set)); ++set) {
            joints.push_back(readAccessor(model, primitive.attributes.at("JOINTS_" + std::to_string(set))));
            weights.push_back(readAccessor(model, primitive.attributes.at("WEIGHTS_" + std::to_string(set))));
        }
        for (std::size_t v = 0; v < positions.size() / 3; ++v) {
            const glm::dvec4 p(positions[v * 3], positions[v * 3 + 1], positions[v * 3 + 2], 1.0);
            glm::dvec4 sum(0.0);
            for (std::size_t s = 0; s < joints.size(); ++s)
                for (std::size_t k = 0; k < 4; ++k)
                    if (weights[s][v * 4 + k] != 0.0)
                        sum += weights[s][v * 4 + k] *
                               (jointMatrix.at(static_cast<std::size_t>(joints[s][v * 4 + k])) * p);
            out.emplace_back(sum);
        }
    }
    return out;
}

}  // namespace test
