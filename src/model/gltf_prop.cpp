// loadGltfProp: the glTF loader's document, accessor and mesh code, without a skin.
#include "model/gltf_prop.h"

#include "gpu/error.h"
#include "model/gltf_internal.h"
#include "model/gltf_loader.h"
#include "model/lod_builder.h"

namespace model {
namespace {

using namespace gltf;

// A model of one joint at the origin holding the mesh, which is what buildLods and propFromModel take.
SkinnedModel rigidModel(const tinygltf::Model& document, const std::string& name, std::vector<std::string>& notes) {
    if (document.meshes.empty()) fail("no mesh (a prop is the file's first mesh)");
    SkinnedModel scratch;
    scratch.name = name;
    scratch.skeleton.parents = {-1};
    scratch.skeleton.jointNames = {"root"};
    scratch.skeleton.restPose = {anim::Transform{}};
    scratch.skeleton.inverseBind = {glm::mat4(1.0f)};
    Palette palette;
    appendRigidMesh(document, 0, palette, scratch, notes);
    if (scratch.indices.empty()) fail("mesh 0 has no triangles");
    scratch.uvs.clear();  // a prop is coloured by its base-colour factors alone
    if (palette.texturedEntries != 0) notes.push_back("base-colour textures ignored: a prop takes the factors alone");
    if (document.meshes.size() > 1) notes.push_back(std::to_string(document.meshes.size() - 1) + " mesh(es) after the first ignored");
    scratch.materialColors = palette.colors;
    return scratch;
}

}  // namespace

PropMesh loadGltfProp(const std::filesystem::path& path, std::vector<std::string>* notes,
                      const std::filesystem::path& assetRoot) {
    const std::string source = path.string();
    const std::vector<std::uint8_t> bytes = readGltfFile(path);
    const std::filesystem::path directory = path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
    std::vector<std::string> localNotes;
    SkinnedModel scratch;
    try {
        EncodedImages images;
        const tinygltf::Model document = parseDocument(bytes, directory, assetRoot, images, localNotes);
        checkRequiredExtensions(document);
        scratch = rigidModel(document, path.stem().string(), localNotes);
    } catch (const gpu::Error& error) {
        throw gpu::Error(source + ": " + error.what());
    }
    if (notes)
        for (const std::string& note : localNotes) notes->push_back(source + ": " + note);
    buildLods(scratch);
    return propFromModel(scratch);
}

}  // namespace model
