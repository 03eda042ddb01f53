// The node hierarchy (checked to be a forest) and the skeleton of a skin: its joints, every node
// between them, and the nodes above them, either kept as joints (when animated or branching) or
// folded into Skeleton::rootTransform. glTF defines a joint's matrix from its global transform, so
// every node on the way to the scene root counts, whether or not the skin lists it.
#include <algorithm>
#include <cmath>

#include <glm/gtc/type_ptr.hpp>

#include "model/gltf_internal.h"
#include "model/gltf_loader.h"

namespace model::gltf {
namespace {

std::string nodeName(int node) { return "node " + std::to_string(node); }

void checkLength(const std::vector<double>& values, std::size_t expected, int node, const char* property) {
    if (!values.empty() && values.size() != expected)
        fail(nodeName(node) + ": " + property + " has " + std::to_string(values.size()) + " numbers (expected " +
             std::to_string(expected) + ")");
}

glm::mat4 readMatrix(const std::vector<double>& values, const std::string& what) {
    glm::mat4 m(1.0f);
    for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = toFloat(values[static_cast<std::size_t>(i)], what);
    return m;
}

// T * R * S of a matrix that has no shear; a sheared joint matrix loses its shear (glTF requires
// node matrices to be decomposable, so only invalid files have one).
anim::Transform decompose(const glm::mat4& m) {
    anim::Transform t;
    t.translation = glm::vec3(m[3]);
    glm::vec3 axes[3] = {glm::vec3(m[0]), glm::vec3(m[1]), glm::vec3(m[2])};
    t.scale = {glm::length(axes[0]), glm::length(axes[1]), glm::length(axes[2])};
    if (glm::determinant(glm::mat3(m)) < 0.0f) t.scale.x = -t.scale.x;
    if (std::abs(t.scale.x) > 1e-20f && std::abs(t.scale.y) > 1e-20f && std::abs(t.scale.z) > 1e-20f) {
        const glm::mat3 rotation(axes[0] / t.scale.x, axes[1] / t.scale.y, axes[2] / t.scale.z);
        t.rotation = glm::normalize(glm::quat_cast(rotation));
    }
    return t;
}

}  // namespace

std::vector<int> nodeParents(const tinygltf::Model& model) {
    const int count = static_cast<int>(model.nodes.size());
    std::vector<int> parents(model.nodes.size(), -1);
    for (int p = 0; p < count; ++p) {
        for (const int c : model.nodes[static_cast<std::size_t>(p)].children) {
            if (c < 0 || c >= count)
                fail(nodeName(p) + " lists child " + std::to_string(c) + ", which does not exist (the file has " +
                     std::to_string(count) + " nodes)");
            if (c == p) fail(nodeName(p) + " is its own child (the node graph has a cycle)");
            int& parent = parents[static_cast<std::size_t>(c)];
            if (parent == p) fail(nodeName(p) + " lists child " + std::to_string(c) + " twice");
            if (parent != -1)
                fail(nodeName(c) + " has two parents (nodes " + std::to_string(parent) + " and " + std::to_string(p) +
                     "); glTF nodes must form trees");
            parent = p;
        }
    }
    // With one parent each, a cycle is a walk upwards that meets itself. 0: unvisited, 1: on the
    // current walk, 2: known to reach a root.
    std::vector<std::uint8_t> state(parents.size(), 0);
    std::vector<int> walk;
    for (int start = 0; start < count; ++start) {
        walk.clear();
        int n = start;
        while (n != -1 && state[static_cast<std::size_t>(n)] == 0) {
            state[static_cast<std::size_t>(n)] = 1;
            walk.push_back(n);
            n = parents[static_cast<std::size_t>(n)];
        }
        if (n != -1 && state[static_cast<std::size_t>(n)] == 1)
            fail("the node graph has a cycle through " + nodeName(n) + " (glTF nodes must form trees)");
        for (const int w : walk) state[static_cast<std::size_t>(w)] = 2;
    }
    return parents;
}

anim::Transform nodeTransform(const tinygltf::Model& model, int index) {
    const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(index)];
    checkLength(node.matrix, 16, index, "matrix");
    checkLength(node.translation, 3, index, "translation");
    checkLength(node.rotation, 4, index, "rotation");
    checkLength(node.scale, 3, index, "scale");
    const std::string what = nodeName(index);
    if (!node.matrix.empty()) return decompose(readMatrix(node.matrix, what + " matrix"));
    anim::Transform t;
    if (!node.translation.empty())
        for (int i = 0; i < 3; ++i)
            t.translation[i] = toFloat(node.translation[static_cast<std::size_t>(i)], what + " translation");
    if (!node.scale.empty())
        for (int i = 0; i < 3; ++i) t.scale[i] = toFloat(node.scale[static_cast<std::size_t>(i)], what + " scale");
    if (!node.rotation.empty()) {
        const glm::quat q(toFloat(node.rotation[3], what + " rotation"), toFloat(node.rotation[0], what + " rotation"),
                          toFloat(node.rotation[1], what + " rotation"), toFloat(node.rotation[2], what + " rotation"));
        const float length = glm::length(q);
        if (!(length > 1e-6f) || !std::isfinite(length)) fail(what + ": rotation is not a unit quaternion");
        t.rotation = q / length;
    }
    return t;
}

glm::mat4 nodeMatrix(const tinygltf::Model& model, int index) {
    const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(index)];
    if (node.matrix.size() == 16) return readMatrix(node.matrix, nodeName(index) + " matrix");
    return nodeTransform(model, index).matrix();
}

SkeletonBuild buildSkeleton(const tinygltf::Model& model, const std::vector<int>& parents, int skinIndex,
                            const std::vector<bool>& animated) {
    const tinygltf::Skin& skin = model.skins[static_cast<std::size_t>(skinIndex)];
    const std::string what = "skin " + std::to_string(skinIndex);
    const std::size_t nodeCount = model.nodes.size();
    if (skin.joints.empty()) fail(what + " has no joints");
    if (skin.joints.size() > kMaxGltfJoints)
        fail(what + " has " + std::to_string(skin.joints.size()) + " joints (at most " +
             std::to_string(kMaxGltfJoints) + " are supported)");

    std::vector<bool> isJoint(nodeCount, false);
    for (const int j : skin.joints) {
        if (j < 0 || static_cast<std::size_t>(j) >= nodeCount)
            fail(what + " lists joint node " + std::to_string(j) + ", which does not exist (the file has " +
                 std::to_string(nodeCount) + " nodes)");
        if (isJoint[static_cast<std::size_t>(j)]) fail(what + " lists " + nodeName(j) + " twice");
        isJoint[static_cast<std::size_t>(j)] = true;
    }

    // The skeleton's nodes: the joints and all their ancestors.
    std::vector<bool> inSkeleton(nodeCount, false);
    for (const int j : skin.joints)
        for (int n = j; n != -1 && !inSkeleton[static_cast<std::size_t>(n)]; n = parents[static_cast<std::size_t>(n)])
            inSkeleton[static_cast<std::size_t>(n)] = true;
    auto skeletonChildren = [&](int n) {
        std::vector<int> children;
        for (const int c : model.nodes[static_cast<std::size_t>(n)].children)
            if (inSkeleton[static_cast<std::size_t>(c)]) children.push_back(c);
        return children;
    };

    SkeletonBuild build;
    anim::Skeleton& skeleton = build.skeleton;
    // Fold the trunk above the joints: static, non-joint nodes each leading to every joint. They are
    // the same for every joint, so one matrix stands for all of them.
    std::vector<int> roots;
    for (std::size_t n = 0; n < nodeCount; ++n)
        if (inSkeleton[n] && parents[n] == -1) roots.push_back(static_cast<int>(n));
    if (roots.size() == 1) {
        int n = roots.front();
        for (std::vector<int> children = skeletonChildren(n);
             !isJoint[static_cast<std::size_t>(n)] && !animated[static_cast<std::size_t>(n)] && children.size() == 1;
             children = skeletonChildren(n)) {
            skeleton.rootTransform = skeleton.rootTransform * nodeMatrix(model, n);
            inSkeleton[static_cast<std::size_t>(n)] = false;
            n = children.front();
        }
        roots = {n};
    }
    const auto jointCount = static_cast<std::size_t>(std::count(inSkeleton.begin(), inSkeleton.end(), true));
    if (jointCount > kMaxGltfJoints)
        fail(what + " needs " + std::to_string(jointCount) + " joints (its " + std::to_string(skin.joints.size()) +
             " joints and the nodes above and between them); at most " + std::to_string(kMaxGltfJoints) +
             " are supported");

    // Number the joints depth first so that parents come before children.
    build.jointOfNode.assign(nodeCount, -1);
    std::vector<int> stack(roots.rbegin(), roots.rend());
    while (!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        const auto joint = static_cast<std::int32_t>(skeleton.parents.size());
        build.jointOfNode[static_cast<std::size_t>(n)] = joint;
        const int parentNode = parents[static_cast<std::size_t>(n)];
        skeleton.parents.push_back(parentNode >= 0 && inSkeleton[static_cast<std::size_t>(parentNode)]
                                       ? build.jointOfNode[static_cast<std::size_t>(parentNode)]
                                       : -1);
        const std::string& name = model.nodes[static_cast<std::size_t>(n)].name;
        skeleton.jointNames.push_back(name.empty() ? nodeName(n) : name);
        skeleton.restPose.push_back(nodeTransform(model, n));
        const std::vector<int> children = skeletonChildren(n);
        stack.insert(stack.end(), children.rbegin(), children.rend());
    }

    // Nodes the skin does not list keep an identity inverse bind matrix: no vertex refers to them.
    skeleton.inverseBind.assign(skeleton.parents.size(), glm::mat4(1.0f));
    build.jointOfSkinJoint.reserve(skin.joints.size());
    for (const int j : skin.joints)
        build.jointOfSkinJoint.push_back(static_cast<std::uint32_t>(build.jointOfNode[static_cast<std::size_t>(j)]));
    if (skin.inverseBindMatrices >= 0) {
        const FloatData matrices =
            readFloats(model, skin.inverseBindMatrices,
                       {what + " inverseBindMatrices", {TINYGLTF_TYPE_MAT4}, {TINYGLTF_COMPONENT_TYPE_FLOAT}});
        if (matrices.count < skin.joints.size())
            fail(what + ": " + std::to_string(matrices.count) + " inverse bind matrices for " +
                 std::to_string(skin.joints.size()) + " joints");
        for (std::size_t k = 0; k < skin.joints.size(); ++k)
            skeleton.inverseBind[build.jointOfSkinJoint[k]] = glm::make_mat4(matrices.element(k));
    }
    return build;
}

}  // namespace model::gltf
