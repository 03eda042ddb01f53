#pragma once
// Small glTF documents built by hand for the loader tests: a document as JSON plus one binary
// buffer, written as .gltf text (buffer embedded as a base64 data URI) or as GLB.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/skinned_model.h"

namespace test {

class GltfBuilder {
public:
    GltfBuilder();

    nlohmann::json doc;
    std::vector<std::uint8_t> bin;

    // Appends bytes (4-byte aligned) as a new buffer view; returns its index.
    int view(const std::vector<std::uint8_t>& bytes);
    // Appends an accessor over a new buffer view holding `values`; returns its index.
    int floats(const std::vector<float>& values, const std::string& type);
    int bytes(const std::vector<std::uint8_t>& values, const std::string& type, bool normalized = false);
    int shorts(const std::vector<std::uint16_t>& values, const std::string& type, bool normalized = false);
    int uints(const std::vector<std::uint32_t>& values, const std::string& type);

    // The document with the buffer embedded (data URI), or with buffers left as they are
    // (`embedBuffer` false: the test sets doc["buffers"] itself).
    std::string gltf(bool embedBuffer = true) const;
    // The document as GLB: JSON chunk and BIN chunk.
    std::vector<std::uint8_t> glb() const;
};

std::string base64(const std::vector<std::uint8_t>& bytes);

// The unit rotation of `degrees` about z, as glTF's [x, y, z, w].
std::vector<float> quatZ(float degrees);

// A 1 x 2 m strip of six vertices in three rows (y = 0, 1, 2; x = -0.5, 0.5), bound to joint "root"
// (node 1, at the origin) and joint "tip" (node 2, 1 m above): the bottom row follows root, the
// middle row both half and half, the top row tip. Node 0 "world" (translation 2, 0, 0) holds the
// root and node 3 "body", which draws mesh 0 with skin 0 and has a translation (5, 5, 5) that glTF
// says a skinned mesh ignores. Material 0 is (0.8, 0.2, 0.1, 1). Animation 0 "bend" turns the tip
// about z: 0, 45 and 90 degrees at 0, 0.5 and 1 s (LINEAR).
GltfBuilder stripCharacter();
// Adds animation "hop" to the strip: a STEP channel that lifts the root by 1 m at t = 1 (holding its
// first key until then) and a CUBICSPLINE channel, zero tangents, easing the tip's scale from 1 to 3.
void addHopAnimation(GltfBuilder& b);

// The strip's primitive (mesh 0, primitive 0), for tests that change it.
nlohmann::json& stripPrimitive(GltfBuilder& b);

// A 2 x 2 RGBA PNG: red, green / blue, white. `emptyDataChunkFirst` puts a zero-length IDAT chunk
// before the one with the pixels (legal PNG; it once led stb_image into undefined behaviour).
std::vector<std::uint8_t> png2x2(bool emptyDataChunkFirst = false);

// Loads a document from memory as the loader's users would (name "test.gltf", no external files).
model::SkinnedModel loadText(const std::string& text, std::vector<std::string>* notes = nullptr);
model::SkinnedModel loadBytes(const std::vector<std::uint8_t>& bytes, std::vector<std::string>* notes = nullptr);

}  // namespace test
