#include "support/gltf_builder.h"

#include <cmath>
#include <cstring>

#include "model/gltf_loader.h"

namespace test {
namespace {

constexpr int kByte = 5121, kShort = 5123, kUint = 5125, kFloat = 5126;

int componentsOf(const std::string& type) {
    if (type == "SCALAR") return 1;
    if (type == "VEC2") return 2;
    if (type == "VEC3") return 3;
    if (type == "VEC4") return 4;
    return 16;  // MAT4
}

template <typename T>
int addAccessor(GltfBuilder& b, const std::vector<T>& values, int componentType, const std::string& type,
                bool normalized) {
    std::vector<std::uint8_t> raw(values.size() * sizeof(T));
    if (!raw.empty()) std::memcpy(raw.data(), values.data(), raw.size());
    nlohmann::json accessor = {{"bufferView", b.view(raw)},
                               {"componentType", componentType},
                               {"count", values.size() / static_cast<std::size_t>(componentsOf(type))},
                               {"type", type}};
    if (normalized) accessor["normalized"] = true;
    b.doc["accessors"].push_back(accessor);
    return static_cast<int>(b.doc["accessors"].size()) - 1;
}

void appendU32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

std::uint32_t crc32(const std::uint8_t* data, std::size_t size) {
    std::uint32_t crc = 0xFFFFFFFFu;
    for (std::size_t i = 0; i < size; ++i) {
        crc ^= data[i];
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

std::uint32_t adler32(const std::vector<std::uint8_t>& data) {
    std::uint32_t a = 1, b = 0;
    for (const std::uint8_t c : data) a = (a + c) % 65521, b = (b + a) % 65521;
    return b << 16 | a;
}

void pngChunk(std::vector<std::uint8_t>& png, const char* kind, const std::vector<std::uint8_t>& data) {
    for (int i = 3; i >= 0; --i) png.push_back(static_cast<std::uint8_t>(data.size() >> (8 * i)));
    std::vector<std::uint8_t> body(kind, kind + 4);
    body.insert(body.end(), data.begin(), data.end());
    png.insert(png.end(), body.begin(), body.end());
    const std::uint32_t crc = crc32(body.data(), body.size());
    for (int i = 3; i >= 0; --i) png.push_back(static_cast<std::uint8_t>(crc >> (8 * i)));
}

}  // namespace

GltfBuilder::GltfBuilder() {
    doc = {{"asset", {{"version", "2.0"}}},
           {"bufferViews", nlohmann::json::array()},
           {"accessors", nlohmann::json::array()}};
}

int GltfBuilder::view(const std::vector<std::uint8_t>& bytes) {
    while (bin.size() % 4 != 0) bin.push_back(0);
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes.size()}});
    bin.insert(bin.end(), bytes.begin(), bytes.end());
    return static_cast<int>(doc["bufferViews"].size()) - 1;
}

int GltfBuilder::floats(const std::vector<float>& values, const std::string& type) {
    return addAccessor(*this, values, kFloat, type, false);
}
int GltfBuilder::bytes(const std::vector<std::uint8_t>& values, const std::string& type, bool normalized) {
    return addAccessor(*this, values, kByte, type, normalized);
}
int GltfBuilder::shorts(const std::vector<std::uint16_t>& values, const std::string& type, bool normalized) {
    return addAccessor(*this, values, kShort, type, normalized);
}
int GltfBuilder::uints(const std::vector<std::uint32_t>& values, const std::string& type) {
    return addAccessor(*this, values, kUint, type, false);
}

std::string GltfBuilder::gltf(bool embedBuffer) const {
    nlohmann::json out = doc;
    if (embedBuffer)
        out["buffers"] = {{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}};
    return out.dump(1);
}

std::vector<std::uint8_t> GltfBuilder::glb() const {
    nlohmann::json out = doc;
    out["buffers"] = {{{"byteLength", bin.size()}}};
    std::string text = out.dump();
    while (text.size() % 4 != 0) text += ' ';
    std::vector<std::uint8_t> binary = bin;
    while (binary.size() % 4 != 0) binary.push_back(0);
    std::vector<std::uint8_t> glb;
    appendU32(glb, 0x46546C67);
    appendU32(glb, 2);
    appendU32(glb, static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + binary.size()));
    appendU32(glb, static_cast<std::uint32_t>(text.size()));
    appendU32(glb, 0x4E4F534A);
    glb.insert(glb.end(), text.begin(), text.end());
    appendU32(glb, static_cast<std::uint32_t>(binary.size()));
    appendU32(glb, 0x004E4942);
    glb.insert(glb.end(), binary.begin(), binary.end());
    return glb;
}

std::string base64(const std::vector<std::uint8_t>& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t n = static_cast<std::uint32_t>(bytes[i]) << 16 |
                                (i + 1 < bytes.size() ? static_cast<std::uint32_t>(bytes[i + 1]) << 8 : 0u) |
                                (i + 2 < bytes.size() ? bytes[i + 2] : 0u);
        out += digits[n >> 18 & 63];
        out += digits[n >> 12 & 63];
        out += i + 1 < bytes.size() ? digits[n >> 6 & 63] : '=';
        out += i + 2 < bytes.size() ? digits[n & 63] : '=';
    }
    return out;
}

std::vector<float> quatZ(float degrees) {
    const double half = degrees * 3.14159265358979323846 / 360.0;
    return {0.0f, 0.0f, static_cast<float>(std::sin(half)), static_cast<float>(std::cos(half))};
}

GltfBuilder stripCharacter() {
    GltfBuilder b;
    std::vector<float> positions;
    for (float y : {0.0f, 1.0f, 2.0f})
        for (float x : {-0.5f, 0.5f}) positions.insert(positions.end(), {x, y, 0.0f});
    std::vector<float> normals;
    for (int v = 0; v < 6; ++v) normals.insert(normals.end(), {0.0f, 0.0f, 1.0f});
    const nlohmann::json attributes = {
        {"POSITION", b.floats(positions, "VEC3")},
        {"NORMAL", b.floats(normals, "VEC3")},
        {"JOINTS_0", b.shorts({0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, "VEC4")},
        {"WEIGHTS_0",
         b.floats({1, 0, 0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0, 0.5f, 0.5f, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, "VEC4")}};
    const int indices = b.shorts({0, 1, 3, 0, 3, 2, 2, 3, 5, 2, 5, 4}, "SCALAR");
    b.doc["meshes"] = {{{"primitives", {{{"attributes", attributes}, {"indices", indices}, {"material", 0}}}}}};
    b.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.2, 0.1, 1.0}}}}}};
    const int inverseBind = b.floats({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0,  0, 1,  //
                                      1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1},
                                     "MAT4");
    b.doc["skins"] = {{{"joints", {1, 2}}, {"inverseBindMatrices", inverseBind}}};
    b.doc["nodes"] = {{{"name", "world"}, {"children", {1, 3}}, {"translation", {2, 0, 0}}},
                      {{"name", "root"}, {"children", {2}}},
                      {{"name", "tip"}, {"translation", {0, 1, 0}}},
                      {{"name", "body"}, {"mesh", 0}, {"skin", 0}, {"translation", {5, 5, 5}}}};
    b.doc["scenes"] = {{{"nodes", {0}}}};
    b.doc["scene"] = 0;
    std::vector<float> rotations;
    for (float degrees : {0.0f, 45.0f, 90.0f}) {
        const std::vector<float> q = quatZ(degrees);
        rotations.insert(rotations.end(), q.begin(), q.end());
    }
    const int times = b.floats({0.0f, 0.5f, 1.0f}, "SCALAR");
    b.doc["animations"] = {
        {{"name", "bend"},
         {"samplers", {{{"input", times}, {"output", b.floats(rotations, "VEC4")}, {"interpolation", "LINEAR"}}}},
         {"channels", {{{"sampler", 0}, {"target", {{"node", 2}, {"path", "rotation"}}}}}}}};
    return b;
}

nlohmann::json& stripPrimitive(GltfBuilder& b) { return b.doc["meshes"][0]["primitives"][0]; }

std::vector<std::uint8_t> png2x2(bool emptyDataChunkFirst) {
    std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    pngChunk(png, "IHDR", {0, 0, 0, 2, 0, 0, 0, 2, 8, 6, 0, 0, 0});
    const std::vector<std::uint8_t> rows = {0, 255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 0, 255, 255, 255, 255, 255, 255};
    // zlib stream with one stored (uncompressed) block.
    std::vector<std::uint8_t> z = {
        0x78, 0x01, 0x01, static_cast<std::uint8_t>(rows.size()), 0, static_cast<std::uint8_t>(~rows.size()), 0xFF};
    z.insert(z.end(), rows.begin(), rows.end());
    const std::uint32_t adler = adler32(rows);
    for (int i = 3; i >= 0; --i) z.push_back(static_cast<std::uint8_t>(adler >> (8 * i)));
    if (emptyDataChunkFirst) pngChunk(png, "IDAT", {});
    pngChunk(png, "IDAT", z);
    pngChunk(png, "IEND", {});
    return png;
}

model::SkinnedModel loadText(const std::string& text, std::vector<std::string>* notes) {
    return model::loadGltfFromMemory(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()),
                                     "test.gltf", {}, notes);
}

model::SkinnedModel loadBytes(const std::vector<std::uint8_t>& bytes, std::vector<std::string>* notes) {
    return model::loadGltfFromMemory(bytes, "test.gltf", {}, notes);
}

void addHopAnimation(GltfBuilder& b) {
    const int times = b.floats({0.0f, 1.0f}, "SCALAR");
    const int steps = b.floats({0, 0, 0, 0, 1, 0}, "VEC3");
    const int spline = b.floats({0, 0, 0, 1, 1, 1, 0, 0, 0, 0, 0, 0, 3, 3, 3, 0, 0, 0}, "VEC3");
    b.doc["animations"].push_back({{"name", "hop"},
                                   {"samplers",
                                    {{{"input", times}, {"output", steps}, {"interpolation", "STEP"}},
                                     {{"input", times}, {"output", spline}, {"interpolation", "CUBICSPLINE"}}}},
                                   {"channels",
                                    {{{"sampler", 0}, {"target", {{"node", 1}, {"path", "translation"}}}},
                                     {{"sampler", 1}, {"target", {{"node", 2}, {"path", "scale"}}}}}}});
}

}  // namespace test
