#pragma once
// Props from glTF 2.0 files: the first mesh of a file as a rigid mesh, with levels of detail made by
// meshoptimizer as a model's are.
#include <filesystem>
#include <string>
#include <vector>

#include "model/prop_mesh.h"

namespace model {

// The first mesh of the file (meshes[0], every triangle primitive of it) in its own space: positions,
// normals (computed where the file has none) and each primitive's base-colour factor; no skin, node
// transform, texture or animation is read. Its levels are built by model::buildLods, as a model's.
// The prop is named after the file's stem. Bad input gives one gpu::Error "<file>: <problem>" (the
// glTF loader's checks and messages); what it leaves out is noted in `notes`, one line each.
PropMesh loadGltfProp(const std::filesystem::path& path, std::vector<std::string>* notes = nullptr,
                      const std::filesystem::path& assetRoot = {});

}  // namespace model
