// A skinned glTF mesh's primitives as one triangle list: triangles from lists, strips and fans,
// index buffers for non-indexed primitives, area-weighted normals where the file has none, and the
// four largest joint influences of each vertex, renormalized.
#include <algorithm>
#include <array>
#include <cmath>

#include <glm/gtc/type_ptr.hpp>

#include "model/gltf_internal.h"

namespace model::gltf {
namespace {

// Most vertices and triangle corners a character may have in all (16 Mi and 48 Mi): far beyond
// crowd characters, and they bound the memory a file can ask for (primitives may share accessors).
constexpr std::size_t kMaxVertices = std::size_t{1} << 24;
constexpr std::size_t kMaxCorners = 3 * kMaxVertices;

const std::vector<int> kFloat = {TINYGLTF_COMPONENT_TYPE_FLOAT};
// Float, or the integer types KHR_mesh_quantization allows (normalized or not).
const std::vector<int> kFloatOrQuantized = {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE,
                                            TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT,
                                            TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};
const std::vector<int> kUnsignedSmall = {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};
const std::vector<int> kWeightTypes = {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                       TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};
const std::vector<int> kIndexTypes = {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                      TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT};

int attribute(const tinygltf::Primitive& primitive, const std::string& name) {
    const auto found = primitive.attributes.find(name);
    return found == primitive.attributes.end() ? -1 : found->second;
}

// Triangles of a primitive as a list of vertex numbers, whatever its mode.
std::vector<std::uint32_t> triangleList(const std::vector<std::uint32_t>& indices, int mode, const std::string& what) {
    const std::size_t n = indices.size();
    std::vector<std::uint32_t> list;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        if (n % 3 != 0) fail(what + ": " + std::to_string(n) + " indices is not a whole number of triangles");
        return indices;
    }
    if (n < 3) return list;
    list.reserve((n - 2) * 3);
    for (std::size_t i = 0; i + 2 < n; ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            // glTF: triangle i is {i, i + 1 + i % 2, i + 2 - i % 2}, keeping every triangle's winding.
            const std::size_t odd = i % 2;
            list.insert(list.end(), {indices[i], indices[i + 1 + odd], indices[i + 2 - odd]});
        } else {  // fan: {i + 1, i + 2, 0}
            list.insert(list.end(), {indices[i + 1], indices[i + 2], indices[0]});
        }
    }
    return list;
}

// Area-weighted vertex normals: each triangle adds its unnormalized face normal (twice its area).
std::vector<glm::vec3> areaWeightedNormals(const FloatData& positions, const std::vector<std::uint32_t>& triangles) {
    std::vector<glm::dvec3> sum(positions.count, glm::dvec3(0.0));
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const glm::dvec3 a(glm::make_vec3(positions.element(triangles[t])));
        const glm::dvec3 b(glm::make_vec3(positions.element(triangles[t + 1])));
        const glm::dvec3 c(glm::make_vec3(positions.element(triangles[t + 2])));
        const glm::dvec3 n = glm::cross(b - a, c - a);
        for (std::size_t k = 0; k < 3; ++k) sum[triangles[t + k]] += n;
    }
    std::vector<glm::vec3> normals(positions.count);
    for (std::size_t v = 0; v < normals.size(); ++v) {
        const double length = glm::length(sum[v]);
        // A vertex on no triangle, or only on degenerate ones, has no direction; any unit vector does.
        normals[v] = length > 0.0 && std::isfinite(length) ? glm::vec3(sum[v] / length) : glm::vec3(0.0f, 1.0f, 0.0f);
    }
    return normals;
}

struct InfluenceSet {
    UintData joints;
    FloatData weights;
};

// Every JOINTS_n / WEIGHTS_n pair of the primitive, in order (at least set 0).
std::vector<InfluenceSet> readInfluences(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                         std::size_t vertexCount, const std::string& what) {
    std::vector<InfluenceSet> sets;
    for (int s = 0;; ++s) {
        const std::string joints = "JOINTS_" + std::to_string(s), weights = "WEIGHTS_" + std::to_string(s);
        const int j = attribute(primitive, joints), w = attribute(primitive, weights);
        if (j < 0 && w < 0) break;
        if (j < 0 || w < 0)
            fail(what + ": " + (j < 0 ? weights + " without " + joints : joints + " without " + weights));
        InfluenceSet set{readUints(model, j, {what + " " + joints, {TINYGLTF_TYPE_VEC4}, kUnsignedSmall}),
                         readFloats(model, w, {what + " " + weights, {TINYGLTF_TYPE_VEC4}, kWeightTypes})};
        if (set.joints.count < vertexCount || set.weights.count < vertexCount)
            fail(what + ": " + joints + "/" + weights + " have fewer elements than its " + std::to_string(vertexCount) +
                 " vertices");
        sets.push_back(std::move(set));
    }
    if (sets.empty()) fail(what + ": no JOINTS_0/WEIGHTS_0 (every primitive of a skinned mesh needs them)");
    return sets;
}

struct Influence {
    std::uint32_t joint;
    float weight;
};

// The four largest influences of vertex v over all sets (the same joint listed twice counts once,
// with the weights added), renormalized to sum to 1. Returns false for a vertex with no weight.
bool strongestFour(const std::vector<InfluenceSet>& sets, std::size_t v, std::size_t skinJoints,
                   gpu::SkinVertex& vertex, const std::string& what) {
    std::vector<Influence> all;
    for (const InfluenceSet& set : sets) {
        for (std::size_t k = 0; k < 4; ++k) {
            const float weight = set.weights.values[v * 4 + k];
            const std::uint32_t joint = set.joints.values[v * 4 + k];
            if (weight < 0.0f) fail(what + ": vertex " + std::to_string(v) + " has a negative weight");
            if (weight == 0.0f) continue;  // unused slot: exporters leave any joint number there
            if (joint >= skinJoints)
                fail(what + ": vertex " + std::to_string(v) + " uses joint " + std::to_string(joint) +
                     ", beyond the skin's " + std::to_string(skinJoints) + " joints");
            const auto same =
                std::find_if(all.begin(), all.end(), [&](const Influence& i) { return i.joint == joint; });
            if (same != all.end())
                same->weight += weight;
            else
                all.push_back({joint, weight});
        }
    }
    std::stable_sort(all.begin(), all.end(),
                     [](const Influence& a, const Influence& b) { return a.weight > b.weight; });
    if (all.size() > MAX_INFLUENCES) all.resize(MAX_INFLUENCES);
    float sum = 0.0f;
    for (const Influence& i : all) sum += i.weight;
    if (!(sum > 0.0f) || !std::isfinite(sum)) return false;
    vertex.joints = glm::uvec4(0u);
    vertex.weights = glm::vec4(0.0f);
    for (std::size_t k = 0; k < all.size(); ++k) {
        vertex.joints[static_cast<int>(k)] = all[k].joint;
        vertex.weights[static_cast<int>(k)] = all[k].weight / sum;
    }
    return true;
}

// `jointOfSkinJoint` null: a rigid mesh (a prop), every vertex on joint 0 and JOINTS/WEIGHTS not read.
void appendPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive, const std::string& what,
                     const std::vector<std::uint32_t>* jointOfSkinJoint, Palette& palette, SkinnedModel& out,
                     std::vector<std::string>& notes) {
    const int positionAccessor = attribute(primitive, "POSITION");
    if (positionAccessor < 0) fail(what + ": no POSITION");
    const FloatData positions =
        readFloats(model, positionAccessor, {what + " POSITION", {TINYGLTF_TYPE_VEC3}, kFloatOrQuantized});
    const std::size_t n = positions.count;
    if (out.vertices.size() + n > kMaxVertices)
        fail(what + ": the character would have more than " + std::to_string(kMaxVertices) + " vertices");
    const std::vector<InfluenceSet> influences =
        jointOfSkinJoint ? readInfluences(model, primitive, n, what) : std::vector<InfluenceSet>{};

    std::vector<std::uint32_t> indices;
    if (primitive.indices >= 0) {
        indices = readUints(model, primitive.indices, {what + " indices", {TINYGLTF_TYPE_SCALAR}, kIndexTypes}).values;
        for (std::size_t i = 0; i < indices.size(); ++i)
            if (indices[i] >= n)
                fail(what + ": index " + std::to_string(i) + " is vertex " + std::to_string(indices[i]) +
                     ", beyond its " + std::to_string(n) + " vertices");
    } else {
        indices.resize(n);
        for (std::size_t i = 0; i < n; ++i) indices[i] = static_cast<std::uint32_t>(i);
    }
    const std::vector<std::uint32_t> triangles = triangleList(indices, primitive.mode, what);
    if (out.indices.size() + triangles.size() > kMaxCorners)
        fail(what + ": the character would have more than " + std::to_string(kMaxCorners / 3) + " triangles");

    std::vector<glm::vec3> normals(n);
    std::vector<bool> haveNormal(n, false);
    if (const int normalAccessor = attribute(primitive, "NORMAL"); normalAccessor >= 0) {
        const FloatData read =
            readFloats(model, normalAccessor, {what + " NORMAL", {TINYGLTF_TYPE_VEC3}, kFloatOrQuantized});
        if (read.count < n) fail(what + ": NORMAL has fewer elements than its " + std::to_string(n) + " vertices");
        for (std::size_t v = 0; v < n; ++v) {
            const glm::vec3 normal = glm::make_vec3(read.element(v));
            const float length = glm::length(normal);
            if (length > 1e-12f && std::isfinite(length)) normals[v] = normal / length, haveNormal[v] = true;
        }
    }
    if (std::find(haveNormal.begin(), haveNormal.end(), false) != haveNormal.end()) {
        const std::vector<glm::vec3> computed = areaWeightedNormals(positions, triangles);
        for (std::size_t v = 0; v < n; ++v)
            if (!haveNormal[v]) normals[v] = computed[v];
    }

    const std::uint32_t material = paletteEntry(model, primitive.material, palette, notes);
    const std::string uvName = "TEXCOORD_" + std::to_string(palette.texCoord);
    if (const int uvAccessor = attribute(primitive, uvName); uvAccessor >= 0) {
        const FloatData uvs =
            readFloats(model, uvAccessor, {what + " " + uvName, {TINYGLTF_TYPE_VEC2}, kFloatOrQuantized});
        if (uvs.count < n)
            fail(what + ": " + uvName + " has fewer elements than its " + std::to_string(n) + " vertices");
        out.uvs.resize(out.vertices.size(), glm::vec2(0.0f));
        for (std::size_t v = 0; v < n; ++v) out.uvs.push_back(glm::make_vec2(uvs.element(v)));
    } else if (!out.uvs.empty()) {
        out.uvs.resize(out.vertices.size() + n, glm::vec2(0.0f));
    }

    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    std::size_t weightless = 0;
    for (std::size_t v = 0; v < n; ++v) {
        gpu::SkinVertex vertex;
        vertex.position = glm::vec4(glm::make_vec3(positions.element(v)), 1.0f);
        vertex.normal = glm::vec4(normals[v], static_cast<float>(material));
        if (!jointOfSkinJoint) {
            vertex.joints = glm::uvec4(0u);
            vertex.weights = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
            out.vertices.push_back(vertex);
            continue;
        }
        if (!strongestFour(influences, v, jointOfSkinJoint->size(), vertex, what)) {
            // No weight at all: glTF leaves such a vertex undefined; follow the skin's first joint
            // (as three.js and Babylon do) rather than collapse it to the origin.
            vertex.joints = glm::uvec4(0u);
            vertex.weights = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
            ++weightless;
        }
        for (int k = 0; k < MAX_INFLUENCES; ++k) vertex.joints[k] = (*jointOfSkinJoint)[vertex.joints[k]];
        out.vertices.push_back(vertex);
    }
    if (weightless > 0)
        notes.push_back(what + ": " + std::to_string(weightless) +
                        " vertices without weights follow the skin's first joint");
    out.indices.reserve(out.indices.size() + triangles.size());
    for (const std::uint32_t i : triangles) out.indices.push_back(base + i);
}

void appendMeshPrimitives(const tinygltf::Model& model, int mesh, const std::vector<std::uint32_t>* jointOfSkinJoint,
                          Palette& palette, SkinnedModel& out, std::vector<std::string>& notes) {
    if (mesh < 0 || static_cast<std::size_t>(mesh) >= model.meshes.size())
        fail("mesh " + std::to_string(mesh) + " does not exist (the file has " + std::to_string(model.meshes.size()) +
             ")");
    const tinygltf::Mesh& source = model.meshes[static_cast<std::size_t>(mesh)];
    for (std::size_t p = 0; p < source.primitives.size(); ++p) {
        const tinygltf::Primitive& primitive = source.primitives[p];
        const std::string what = "mesh " + std::to_string(mesh) + " primitive " + std::to_string(p);
        if (primitive.mode >= TINYGLTF_MODE_POINTS && primitive.mode <= TINYGLTF_MODE_LINE_STRIP) {
            notes.push_back(what + " draws points or lines; skipped");
            continue;
        }
        if (primitive.mode < TINYGLTF_MODE_TRIANGLES || primitive.mode > TINYGLTF_MODE_TRIANGLE_FAN)
            fail(what + ": unknown mode " + std::to_string(primitive.mode));
        if (!primitive.targets.empty()) notes.push_back(what + ": morph targets ignored");
        appendPrimitive(model, primitive, what, jointOfSkinJoint, palette, out, notes);
    }
}

}  // namespace

void appendMesh(const tinygltf::Model& model, int mesh, const std::vector<std::uint32_t>& jointOfSkinJoint,
                Palette& palette, SkinnedModel& out, std::vector<std::string>& notes) {
    appendMeshPrimitives(model, mesh, &jointOfSkinJoint, palette, out, notes);
}

void appendRigidMesh(const tinygltf::Model& model, int mesh, Palette& palette, SkinnedModel& out,
                     std::vector<std::string>& notes) {
    appendMeshPrimitives(model, mesh, nullptr, palette, out, notes);
}

}  // namespace model::gltf
