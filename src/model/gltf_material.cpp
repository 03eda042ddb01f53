// Materials as palette entries (base colour factor, linear RGBA) and the one base-colour texture a
// character may carry, decoded from PNG or JPEG only.
#include <algorithm>
#include <climits>
#include <cstring>
#include <limits>

#include <stb/stb_image.h>

#include "model/gltf_internal.h"
#include "model/gltf_loader.h"

namespace model::gltf {
namespace {

glm::vec4 baseColor(const tinygltf::Model& model, int material) {
    if (material < 0) return glm::vec4(1.0f);  // glTF's default material is white
    const std::vector<double>& factor =
        model.materials[static_cast<std::size_t>(material)].pbrMetallicRoughness.baseColorFactor;
    const std::string what = "material " + std::to_string(material) + " baseColorFactor";
    if (factor.size() != 4) fail(what + " has " + std::to_string(factor.size()) + " numbers (expected 4)");
    glm::vec4 color;
    for (int i = 0; i < 4; ++i) color[i] = std::clamp(toFloat(factor[static_cast<std::size_t>(i)], what), 0.0f, 1.0f);
    return color;
}

bool isPng(std::span<const std::uint8_t> b) {
    static const std::uint8_t magic[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    return b.size() >= 8 && std::memcmp(b.data(), magic, 8) == 0;
}

bool isJpeg(std::span<const std::uint8_t> b) { return b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF; }

std::uint32_t bigEndian32(std::span<const std::uint8_t> b, std::size_t at) {
    return static_cast<std::uint32_t>(b[at]) << 24 | static_cast<std::uint32_t>(b[at + 1]) << 16 |
           static_cast<std::uint32_t>(b[at + 2]) << 8 | b[at + 3];
}

// The PNG without its zero-length IDAT chunks. They carry no data, but stb_image copies one into a
// still-null buffer (memcpy(NULL, p, 0): undefined behaviour, found by the fuzzer). The walk stops
// at a chunk that runs past the end; stb_image rejects the rest itself.
std::vector<std::uint8_t> withoutEmptyDataChunks(std::span<const std::uint8_t> png) {
    std::vector<std::uint8_t> out(png.begin(), png.begin() + 8);
    std::size_t at = 8;
    while (png.size() - at >= 12) {
        const std::uint32_t length = bigEndian32(png, at);
        if (length > png.size() - at - 12) break;
        const bool emptyData = length == 0 && std::memcmp(png.data() + at + 4, "IDAT", 4) == 0;
        if (!emptyData)
            out.insert(out.end(), png.begin() + static_cast<std::ptrdiff_t>(at),
                       png.begin() + static_cast<std::ptrdiff_t>(at + 12 + length));
        at += 12 + length;
    }
    out.insert(out.end(), png.begin() + static_cast<std::ptrdiff_t>(at), png.end());
    return out;
}

}  // namespace

std::uint32_t paletteEntry(const tinygltf::Model& model, int material, Palette& palette,
                           std::vector<std::string>& notes) {
    if (material < -1 || material >= static_cast<int>(model.materials.size()))
        fail("material " + std::to_string(material) + " does not exist (the file has " +
             std::to_string(model.materials.size()) + ")");
    if (const auto found = palette.entryOfMaterial.find(material); found != palette.entryOfMaterial.end())
        return found->second;

    const glm::vec4 color = baseColor(model, material);
    bool textured = false;
    if (material >= 0) {
        const tinygltf::TextureInfo& info =
            model.materials[static_cast<std::size_t>(material)].pbrMetallicRoughness.baseColorTexture;
        if (info.index >= 0) {
            if (static_cast<std::size_t>(info.index) >= model.textures.size())
                fail("material " + std::to_string(material) + ": texture " + std::to_string(info.index) +
                     " does not exist (the file has " + std::to_string(model.textures.size()) + ")");
            if (info.texCoord < 0 || info.texCoord > 7)
                fail("material " + std::to_string(material) + ": texCoord " + std::to_string(info.texCoord) +
                     " is out of range");
            if (palette.texture < 0) {
                palette.texture = info.index;
                palette.texCoord = info.texCoord;
            }
            textured = info.index == palette.texture && info.texCoord == palette.texCoord;
            if (!textured)
                notes.push_back(
                    "material " + std::to_string(material) +
                    " uses a second base-colour texture; only the first is kept, it gets its colour factor alone");
        }
    }

    std::uint32_t entry = 0;
    if (palette.colors.size() < MAX_MODEL_MATERIALS) {
        entry = static_cast<std::uint32_t>(palette.colors.size());
        palette.colors.push_back(color);
        if (textured) palette.texturedEntries |= 1u << entry;
    } else {
        // The GPU palette has MAX_MODEL_MATERIALS entries: share the nearest colour.
        float best = std::numeric_limits<float>::max();
        for (std::size_t i = 0; i < palette.colors.size(); ++i) {
            const glm::vec4 d = palette.colors[i] - color;
            if (glm::dot(d, d) < best) best = glm::dot(d, d), entry = static_cast<std::uint32_t>(i);
        }
        notes.push_back("more than " + std::to_string(MAX_MODEL_MATERIALS) + " materials: material " +
                        std::to_string(material) + " shares the nearest colour");
    }
    palette.entryOfMaterial[material] = entry;
    return entry;
}

void decodeBaseColorTexture(const tinygltf::Model& model, const EncodedImages& images, const Palette& palette,
                            SkinnedModel& out, std::vector<std::string>& notes) {
    if (palette.texture < 0 || palette.texturedEntries == 0) return;
    const int source = model.textures[static_cast<std::size_t>(palette.texture)].source;
    const std::string what = "texture " + std::to_string(palette.texture);
    if (source < 0 || static_cast<std::size_t>(source) >= model.images.size()) {
        notes.push_back(what + " has no image this loader can read; rendering without it");
        return;
    }
    const tinygltf::Image& image = model.images[static_cast<std::size_t>(source)];
    const std::string imageName = "image " + std::to_string(source) + (image.uri.empty() ? "" : " (" + image.uri + ")");
    std::span<const std::uint8_t> bytes;
    if (image.bufferView >= 0) {
        bytes = bufferViewBytes(model, image.bufferView, imageName);
    } else if (const auto found = images.find(source); found != images.end()) {
        bytes = found->second;
    } else {
        notes.push_back(imageName + " could not be read; rendering without a texture");
        return;
    }
    // glTF allows PNG and JPEG; stb_image would also take other formats, which only widens what a
    // malformed file can reach.
    if (!isPng(bytes) && !isJpeg(bytes)) {
        notes.push_back(imageName + " is neither PNG nor JPEG; rendering without a texture");
        return;
    }
    std::vector<std::uint8_t> cleaned;
    if (isPng(bytes)) bytes = cleaned = withoutEmptyDataChunks(bytes);
    if (bytes.size() > static_cast<std::size_t>(INT_MAX)) {
        notes.push_back(imageName + " is too large; rendering without a texture");
        return;
    }
    const int size = static_cast<int>(bytes.size());
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(bytes.data(), size, &width, &height, &channels)) {
        notes.push_back(imageName + " could not be decoded (" + stbi_failure_reason() +
                        "); rendering without a texture");
        return;
    }
    if (width <= 0 || height <= 0 || width > static_cast<int>(kMaxGltfTextureSide) ||
        height > static_cast<int>(kMaxGltfTextureSide)) {
        notes.push_back(imageName + " is " + std::to_string(width) + "x" + std::to_string(height) + " (at most " +
                        std::to_string(kMaxGltfTextureSide) + " a side); rendering without a texture");
        return;
    }
    stbi_uc* pixels = stbi_load_from_memory(bytes.data(), size, &width, &height, &channels, 4);
    if (pixels == nullptr) {
        notes.push_back(imageName + " could not be decoded (" + stbi_failure_reason() +
                        "); rendering without a texture");
        return;
    }
    out.baseColorTexture.width = static_cast<std::uint32_t>(width);
    out.baseColorTexture.height = static_cast<std::uint32_t>(height);
    out.baseColorTexture.rgba.assign(pixels,
                                     pixels + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    stbi_image_free(pixels);
    out.texturedMaterials = palette.texturedEntries;
}

}  // namespace model::gltf
