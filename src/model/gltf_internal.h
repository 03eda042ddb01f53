#pragma once
// The glTF loader's parts, shared by its files and by nothing else. Every function throws
// gpu::Error with a message that does not name the file; loadGltf() adds the name in front.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include "anim/clip.h"
#include "anim/skeleton.h"
#include "model/skinned_model.h"

namespace model::gltf {

[[noreturn]] void fail(const std::string& problem);

// ---- document (gltf_document.cpp) ----

// Encoded images that tinygltf read from data URIs or external files, by image index (images that
// live in buffer views stay there; see decodeBaseColorTexture).
using EncodedImages = std::map<int, std::vector<std::uint8_t>>;

// Parses a .gltf (JSON) or .glb document. Checks the GLB container, the JSON nesting and the JSON
// types before tinygltf sees them, reads external files through ExternalFiles(baseDir, assetRoot),
// and leaves images encoded in `images`.
tinygltf::Model parseDocument(std::span<const std::uint8_t> bytes, const std::filesystem::path& baseDir,
                              const std::filesystem::path& assetRoot, EncodedImages& images,
                              std::vector<std::string>& notes);

// Checks that every property the loader reads has the JSON type the glTF schema gives it (tinygltf
// drops what it cannot parse, silently changing the character); fails naming the property by its
// path, e.g. "nodes[2].children[0]: expected an index ..., found an object". Notes what the loader
// can ignore (channels that target no node). (gltf_json_types.cpp)
void checkJsonTypes(std::span<const std::uint8_t> json, std::vector<std::string>& notes);

// ---- the file (gltf_loader.cpp) ----

// The bytes of a glTF or GLB file, at most kMaxGltfFileBytes. Throws gpu::Error "<path>: <problem>"
// (no such file, not a regular file, too large, unreadable).
std::vector<std::uint8_t> readGltfFile(const std::filesystem::path& path);

// Fails for an extension the document requires that changes what the loader reads.
void checkRequiredExtensions(const tinygltf::Model& document);

// ---- external files (gltf_external_files.cpp) ----

// The file-system callbacks tinygltf reads every external buffer and image through. A URI must be a
// relative path (no scheme such as file:, not absolute, no control characters) that leads, after
// tinygltf's percent-decoding, ".." and symbolic links, to a regular file inside the asset root
// (`assetRoot`, or `baseDir`, the document's folder, when empty); tinygltf's second try, in the
// working directory, is never read. The first refusal is kept for the error message. With an empty
// `baseDir` (a document from memory) nothing is read. At most kMaxGltfFileBytes in all.
class ExternalFiles {
public:
    ExternalFiles(const std::filesystem::path& baseDir, const std::filesystem::path& assetRoot);
    tinygltf::FsCallbacks callbacks();
    // Why a URI was refused ("URI '../x.bin' leads outside the model's folder ..."), or "".
    const std::string& refusal() const { return refusal_; }
    // The file that tinygltf's path (its search directory joined with the decoded URI) may be read from.
    std::optional<std::filesystem::path> resolve(const std::string& path);
    bool read(const std::string& path, std::vector<unsigned char>& out, std::string* err);

private:
    std::string prefix_;  // the document's folder as tinygltf joins it with URIs
    std::filesystem::path baseDir_;
    std::filesystem::path root_;  // canonical
    bool rootIsModelFolder_;
    std::uint64_t bytesRead_ = 0;
    std::string refusal_;
};

// ---- accessors (gltf_accessors.cpp) ----

// What an accessor may hold where it is read: its allowed types (TINYGLTF_TYPE_*) and component
// types (TINYGLTF_COMPONENT_TYPE_*), and a name for messages ("mesh 0 primitive 1 POSITION").
struct AccessorRule {
    std::string what;
    std::vector<int> types;
    std::vector<int> componentTypes;
};

// An accessor's elements as floats, `components` per element (1 for SCALAR ... 16 for MAT4, column
// major). Integer components convert as glTF says: divided to [0, 1] or [-1, 1] when the accessor
// is normalized, as they are otherwise. Sparse accessors are applied; an accessor without a buffer
// view reads zeros. Throws for an index, offset, stride or count that does not fit.
struct FloatData {
    std::size_t count = 0;
    int components = 0;
    std::vector<float> values;
    const float* element(std::size_t i) const { return values.data() + i * static_cast<std::size_t>(components); }
};
FloatData readFloats(const tinygltf::Model& model, int accessor, const AccessorRule& rule);

// An accessor of unsigned integers (indices, joint numbers), `components` per element.
struct UintData {
    std::size_t count = 0;
    int components = 0;
    std::vector<std::uint32_t> values;
};
UintData readUints(const tinygltf::Model& model, int accessor, const AccessorRule& rule);

// The bytes [offset, offset + length) of a buffer view, checked against its buffer.
std::span<const std::uint8_t> bufferViewBytes(const tinygltf::Model& model, int bufferView, const std::string& what);

// A double from JSON as a finite float, or fail naming `what`.
float toFloat(double value, const std::string& what);

// ---- node hierarchy and skeleton (gltf_skeleton.cpp) ----

// parent[n] of every node (-1 for roots) after checking the children lists: indices in range, no
// node with two parents, no cycles.
std::vector<int> nodeParents(const tinygltf::Model& model);

// A node's local transform as TRS (a matrix is decomposed) and as a matrix (exact for matrices).
anim::Transform nodeTransform(const tinygltf::Model& model, int node);
glm::mat4 nodeMatrix(const tinygltf::Model& model, int node);

struct SkeletonBuild {
    anim::Skeleton skeleton;
    std::vector<int> jointOfNode;                 // per node: its joint, or -1
    std::vector<std::uint32_t> jointOfSkinJoint;  // per entry of skin.joints: its joint
};

// The skeleton of `skin`: its joints, the nodes between them and their animated ancestors, ordered
// parents first; static nodes above fold into rootTransform. `animated[n]` marks nodes that some
// animation channel moves.
SkeletonBuild buildSkeleton(const tinygltf::Model& model, const std::vector<int>& parents, int skin,
                            const std::vector<bool>& animated);

// ---- meshes and materials (gltf_mesh.cpp, gltf_material.cpp) ----

// Material palette under construction: glTF material index (-1: the default material) to palette entry.
struct Palette {
    std::vector<glm::vec4> colors;
    std::map<int, std::uint32_t> entryOfMaterial;
    std::uint32_t texturedEntries = 0;
    int texture = -1;  // the glTF texture every textured entry samples
    int texCoord = 0;  // the TEXCOORD_n set it uses
};

// The palette entry of a material, adding it on first use. Materials beyond MAX_MODEL_MATERIALS share the
// nearest colour already present (with a note).
std::uint32_t paletteEntry(const tinygltf::Model& model, int material, Palette& palette,
                           std::vector<std::string>& notes);

// Appends the triangles of every primitive of `mesh` to `out` (vertices, indices, uvs), remapping
// skin joint numbers through `jointOfSkinJoint`.
void appendMesh(const tinygltf::Model& model, int mesh, const std::vector<std::uint32_t>& jointOfSkinJoint,
                Palette& palette, SkinnedModel& out, std::vector<std::string>& notes);

// The same for a rigid mesh (a prop): every vertex on joint 0 with weight 1; JOINTS_n/WEIGHTS_n are not read.
void appendRigidMesh(const tinygltf::Model& model, int mesh, Palette& palette, SkinnedModel& out,
                     std::vector<std::string>& notes);

// Decodes the image of palette.texture into out.baseColorTexture (PNG or JPEG); a texture that
// cannot be decoded is left out with a note, and out.texturedMaterials stays 0.
void decodeBaseColorTexture(const tinygltf::Model& model, const EncodedImages& images, const Palette& palette,
                            SkinnedModel& out, std::vector<std::string>& notes);

// ---- animations (gltf_animation.cpp) ----

// Nodes that some translation, rotation or scale channel moves.
std::vector<bool> animatedNodes(const tinygltf::Model& model);

// Every animation as a clip of the channels that move skeleton joints.
// A clip whose poses could leave kMaxGltfPoseReach (anim::poseReach with `maxBindDistance`, the
// farthest bind-pose vertex) fails naming the animation and the channel that takes it there; so does
// a rest pose that could.
std::vector<anim::Clip> loadClips(const tinygltf::Model& model, const SkeletonBuild& skeleton, double maxBindDistance,
                                  std::vector<std::string>& notes);

}  // namespace model::gltf
