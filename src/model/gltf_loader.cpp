// loadGltf: the document, its first skinned mesh, that skin's skeleton, the clips, materials and
// bounds, in that order; the parts live in gltf_*.cpp.
#include "model/gltf_loader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <set>
#include <system_error>

#include "anim/local_to_model.h"
#include "gpu/error.h"
#include "model/gltf_internal.h"

namespace model {
namespace {

using namespace gltf;

// Extensions a file may require that change nothing this loader reads (materials and lights are
// shading; quantized attributes are read as normalized integers).
bool harmlessExtension(const std::string& name) {
    return name == "KHR_mesh_quantization" || name == "KHR_texture_transform" || name == "KHR_lights_punctual" ||
           name.rfind("KHR_materials_", 0) == 0;
}


// Nodes of the scene that is shown: the default scene, or the first; every node when there is none.
std::vector<bool> sceneNodes(const tinygltf::Model& document) {
    std::vector<bool> inScene(document.nodes.size(), document.scenes.empty());
    if (document.scenes.empty()) return inScene;
    const int scene = document.defaultScene >= 0 ? document.defaultScene : 0;
    if (static_cast<std::size_t>(scene) >= document.scenes.size())
        fail("scene " + std::to_string(scene) + " does not exist (the file has " +
             std::to_string(document.scenes.size()) + ")");
    std::vector<int> stack;
    for (const int root : document.scenes[static_cast<std::size_t>(scene)].nodes) {
        if (root < 0 || static_cast<std::size_t>(root) >= document.nodes.size())
            fail("scene " + std::to_string(scene) + " lists node " + std::to_string(root) +
                 ", which does not exist (the file has " + std::to_string(document.nodes.size()) + " nodes)");
        stack.push_back(root);
    }
    // nodeParents() has checked that the nodes form trees, so this visits each node once.
    while (!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        if (inScene[static_cast<std::size_t>(n)]) continue;
        inScene[static_cast<std::size_t>(n)] = true;
        for (const int c : document.nodes[static_cast<std::size_t>(n)].children) stack.push_back(c);
    }
    return inScene;
}

// The nodes that draw a skinned mesh: those of the shown scene, or any if the scene has none.
std::vector<int> skinnedMeshNodes(const tinygltf::Model& document, const std::vector<bool>& inScene) {
    std::vector<int> inSceneNodes, anyNodes;
    for (std::size_t n = 0; n < document.nodes.size(); ++n) {
        const tinygltf::Node& node = document.nodes[n];
        if (node.mesh < 0 || node.skin < 0) continue;
        anyNodes.push_back(static_cast<int>(n));
        if (inScene[n]) inSceneNodes.push_back(static_cast<int>(n));
    }
    if (anyNodes.empty()) {
        const bool anyMesh = std::any_of(document.nodes.begin(), document.nodes.end(),
                                         [](const tinygltf::Node& node) { return node.mesh >= 0; });
        fail(anyMesh ? "no skinned mesh: no node has both a mesh and a skin (static models are not supported)"
                     : "no skinned mesh: the file has no mesh nodes");
    }
    return inSceneNodes.empty() ? anyNodes : inSceneNodes;
}

// Bounds of the vertices skinned with the rest pose: where glTF puts the character in its scene when
// no animation plays, which is what the crowd's spacing and camera need.
void computeSkinnedBounds(SkinnedModel& model) {
    const anim::Skeleton& skeleton = model.skeleton;
    std::vector<glm::mat4> global(skeleton.jointCount());
    anim::localToModel(skeleton.parents, skeleton.restPose, skeleton.rootTransform, global);
    for (std::size_t j = 0; j < global.size(); ++j) global[j] = global[j] * skeleton.inverseBind[j];
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const gpu::SkinVertex& v : model.vertices) {
        glm::vec3 p(0.0f);
        for (int k = 0; k < MAX_INFLUENCES; ++k)
            if (v.weights[k] != 0.0f) p += v.weights[k] * glm::vec3(global[v.joints[k]] * v.position);
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            fail("the rest pose places vertices at infinity (check the node transforms and inverse bind matrices)");
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    model.boundsMin = lo;
    model.boundsMax = hi;
}

SkinnedModel buildModel(std::span<const std::uint8_t> bytes, const std::string& modelName,
                        const std::filesystem::path& baseDir, const std::filesystem::path& assetRoot,
                        std::vector<std::string>& notes) {
    EncodedImages images;
    const tinygltf::Model document = parseDocument(bytes, baseDir, assetRoot, images, notes);
    checkRequiredExtensions(document);
    const std::vector<int> parents = nodeParents(document);
    const std::vector<int> meshNodes = skinnedMeshNodes(document, sceneNodes(document));

    const int skin = document.nodes[static_cast<std::size_t>(meshNodes.front())].skin;
    if (static_cast<std::size_t>(skin) >= document.skins.size())
        fail("node " + std::to_string(meshNodes.front()) + " uses skin " + std::to_string(skin) +
             ", which does not exist (the file has " + std::to_string(document.skins.size()) + ")");
    const SkeletonBuild build = buildSkeleton(document, parents, skin, animatedNodes(document));

    SkinnedModel model;
    model.name = modelName;
    model.skeleton = build.skeleton;
    Palette palette;
    std::set<int> meshesDone;
    std::size_t otherSkins = 0;
    // Every mesh bound to the first skin is part of the character. Skinned meshes ignore their own
    // node's transform (the joints place them), so two nodes drawing one mesh would coincide: once.
    for (const int node : meshNodes) {
        const tinygltf::Node& n = document.nodes[static_cast<std::size_t>(node)];
        if (n.skin != skin)
            ++otherSkins;
        else if (meshesDone.insert(n.mesh).second)
            appendMesh(document, n.mesh, build.jointOfSkinJoint, palette, model, notes);
    }
    if (otherSkins > 0)
        notes.push_back(std::to_string(otherSkins) +
                        " mesh node(s) with another skin ignored (one character per file)");
    if (model.indices.empty()) fail("the skinned mesh has no triangles");
    if (!model.uvs.empty()) model.uvs.resize(model.vertices.size(), glm::vec2(0.0f));
    model.materialColors = palette.colors;
    decodeBaseColorTexture(document, images, palette, model, notes);

    double maxBindDistance = 0.0;
    for (const gpu::SkinVertex& v : model.vertices)
        maxBindDistance = std::max(maxBindDistance, glm::length(glm::dvec3(glm::vec3(v.position))));
    model.clips = loadClips(document, build, maxBindDistance, notes);
    if (model.clips.empty()) {
        // The crowd needs a clip to play; a file without animations stands in its rest pose.
        anim::Clip rest;
        rest.name = "rest";
        model.clips.push_back(rest);
    }
    computeSkinnedBounds(model);
    return model;
}

SkinnedModel loadNamed(std::span<const std::uint8_t> bytes, const std::string& source, const std::string& modelName,
                       const std::filesystem::path& baseDir, const std::filesystem::path& assetRoot,
                       std::vector<std::string>* notes) {
    std::vector<std::string> localNotes;
    SkinnedModel model;
    try {
        model = buildModel(bytes, modelName, baseDir, assetRoot, localNotes);
    } catch (const gpu::Error& error) {
        throw gpu::Error(source + ": " + error.what());
    }
    if (notes)
        for (const std::string& note : localNotes) notes->push_back(source + ": " + note);
    return model;
}

}  // namespace

namespace gltf {

void checkRequiredExtensions(const tinygltf::Model& document) {
    for (const std::string& name : document.extensionsRequired)
        if (!harmlessExtension(name)) fail("requires the extension " + name + ", which this loader does not support");
}

std::vector<std::uint8_t> readGltfFile(const std::filesystem::path& path) {
    const std::string source = path.string();
    std::error_code error;
    if (!std::filesystem::exists(path, error)) throw gpu::Error(source + ": no such file");
    if (!std::filesystem::is_regular_file(path, error)) throw gpu::Error(source + ": not a regular file");
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error) throw gpu::Error(source + ": cannot read its size (" + error.message() + ")");
    if (size > kMaxGltfFileBytes) throw gpu::Error(source + ": larger than 1 GiB");
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
    std::ifstream file(path, std::ios::binary);
    if (!file || !file.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size)))
        throw gpu::Error(source + ": cannot read the file");
    return bytes;
}

}  // namespace gltf

bool hasGltfExtension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".gltf" || extension == ".glb";
}

SkinnedModel loadGltfFromMemory(std::span<const std::uint8_t> bytes, const std::string& name,
                                const std::filesystem::path& baseDir, std::vector<std::string>* notes) {
    return loadNamed(bytes, name, name, baseDir, {}, notes);
}

SkinnedModel loadGltf(const std::filesystem::path& path, std::vector<std::string>* notes,
                      const std::filesystem::path& assetRoot) {
    const std::string source = path.string();
    const std::vector<std::uint8_t> bytes = gltf::readGltfFile(path);
    const std::filesystem::path directory =
        path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
    return loadNamed(bytes, source, path.stem().string(), directory, assetRoot, notes);
}

}  // namespace model
