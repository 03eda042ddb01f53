#pragma once
// Skinned characters from glTF 2.0 files (.gltf with embedded or external buffers, or .glb).
//
// The loader takes the first skinned mesh of the file's scene (every mesh bound to that same skin is
// merged into the one character), the skin's joints with the nodes between and above them, every
// animation's translation/rotation/scale channels on those nodes, the materials' base colours and
// the first base-colour texture. docs/gltf.md lists what is supported and what is ignored.
//
// Files are untrusted input: every index, count, offset and value is checked before use, so a
// malformed file gives one gpu::Error "<file>: <problem>" and never a crash, a hang or a huge
// allocation beyond the limits below.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "model/skinned_model.h"

namespace model {

// Most joints a character may have: the skin's joints plus the nodes the loader adds between and
// above them. A crowd character's bones are uploaded every frame for every character (48 bytes
// each), and 256 covers game and film-crowd rigs with fingers; bigger rigs are refused, not cut.
inline constexpr std::uint32_t kMaxGltfJoints = 256;
// Largest file, external buffer or external image read (1 GiB): bounds what a file can make us allocate.
inline constexpr std::uint64_t kMaxGltfFileBytes = 1ull << 30;
// Deepest JSON nesting accepted. Real files need fewer than 10 levels; the limit keeps a file of
// nested brackets from exhausting the stack of the JSON parsers.
inline constexpr int kMaxGltfJsonDepth = 64;
// Largest side of a base-colour texture that is decoded (larger ones are skipped with a note).
inline constexpr std::uint32_t kMaxGltfTextureSide = 8192;
// Farthest from the model's origin that any pose of any clip may put a vertex, by the bound of
// anim::poseReach (which also bounds how far a bone matrix stretches a unit vector). Finite keys near
// the float limit would animate into inf and NaN; 1e18 keeps squared lengths (lighting, depth) well
// inside float range, with room for the crowd's placement. Real characters stay below 1e6.
inline constexpr double kMaxGltfPoseReach = 1e18;

// Loads the character in `path`. Throws gpu::Error with one line naming the file and the problem.
// Problems that still leave a usable character (an undecodable texture, a second skin, point
// primitives) are appended to `notes` when given, one line each.
//
// External buffers and images are read only where their URIs lead, after "..", percent-decoding and
// symbolic links, inside the asset root: `assetRoot`, or the file's own folder when empty (the
// programs' --asset-root). A URI that leads outside it, an absolute path and a URI with a scheme
// (file:, http:) are errors that name the URI; nothing outside is read or measured.
SkinnedModel loadGltf(const std::filesystem::path& path, std::vector<std::string>* notes = nullptr,
                      const std::filesystem::path& assetRoot = {});

// The same from bytes in memory; `name` names the source in messages and becomes the model's name.
// External files (buffers, images) resolve against `baseDir`, which is also the asset root; with an
// empty `baseDir` a reference to an external file is an error (so fuzzing and tests never touch the
// file system).
SkinnedModel loadGltfFromMemory(std::span<const std::uint8_t> bytes, const std::string& name,
                                const std::filesystem::path& baseDir = {}, std::vector<std::string>* notes = nullptr);

// True for names the loader should be given: ".gltf" or ".glb" (any case).
bool hasGltfExtension(const std::filesystem::path& path);

}  // namespace model
