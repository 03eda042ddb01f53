#pragma once
// glTF skinning evaluated straight from the specification, to test the loader against: it reads
// tinygltf's parsed document (not the loader's SkinnedModel), walks the node tree for global
// transforms, samples animations with its own code, and skins every influence in double precision.
#include <filesystem>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

namespace test {

// Parses a file with tinygltf directly (throws std::runtime_error when tinygltf fails).
tinygltf::Model parseWithTinygltf(const std::filesystem::path& path);

// World-space positions of the first skinned mesh's vertices (every primitive, in order), with
// animation `animation` at `time` seconds, or the nodes' rest transforms when `animation` is -1:
// jointMatrix = globalTransform(joint) * inverseBindMatrix, vertex = sum of weight * jointMatrix * position.
std::vector<glm::dvec3> referenceSkinnedPositions(const tinygltf::Model& model, int animation, double time);

}  // namespace test
