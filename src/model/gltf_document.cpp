// The glTF container: checks what tinygltf trusts (the GLB chunk table, JSON nesting, external
// files) before handing the document to it.
#include <cstring>

#include "gpu/error.h"
#include "model/gltf_internal.h"
#include "model/gltf_loader.h"

namespace model::gltf {

void fail(const std::string& problem) { throw gpu::Error(problem); }

namespace {

constexpr std::uint32_t kGlbMagic = 0x46546C67;   // "glTF"
constexpr std::uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942;   // "BIN\0"
constexpr std::size_t kGlbHeaderBytes = 12;
constexpr std::size_t kChunkHeaderBytes = 8;

std::uint32_t readU32(std::span<const std::uint8_t> bytes, std::size_t offset) {
    return static_cast<std::uint32_t>(bytes[offset]) | static_cast<std::uint32_t>(bytes[offset + 1]) << 8 |
           static_cast<std::uint32_t>(bytes[offset + 2]) << 16 | static_cast<std::uint32_t>(bytes[offset + 3]) << 24;
}

// tinygltf's JSON parser and its conversion of "extras" recurse once per nesting level; a file of a
// million '[' would overflow the stack, so nesting is bounded before either runs.
void checkJsonNesting(std::span<const std::uint8_t> json) {
    int depth = 0;
    bool inString = false, escaped = false;
    for (const std::uint8_t c : json) {
        if (inString) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxGltfJsonDepth)
                fail("JSON nested deeper than " + std::to_string(kMaxGltfJsonDepth) + " levels");
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
}

// The bytes to give tinygltf for a GLB file, after checking its header and chunk table against the
// file's size (tinygltf 2.7 reads up to 8 bytes past a BIN chunk that ends at the end of the file).
// What tinygltf must not see unchecked in the JSON: its nesting (before any parser recurses into it),
// then the types of the properties the loader reads.
void checkJson(std::span<const std::uint8_t> json, std::vector<std::string>& notes) {
    checkJsonNesting(json);
    checkJsonTypes(json, notes);
}

std::span<const std::uint8_t> checkGlb(std::span<const std::uint8_t> bytes, std::vector<std::uint8_t>& patched,
                                       std::vector<std::string>& notes) {
    if (bytes.size() < kGlbHeaderBytes + kChunkHeaderBytes)
        fail("truncated GLB: " + std::to_string(bytes.size()) + " bytes is shorter than the GLB header");
    const std::uint32_t version = readU32(bytes, 4);
    if (version != 2) fail("GLB version " + std::to_string(version) + " (only glTF 2.0 is supported)");
    const std::uint32_t length = readU32(bytes, 8);
    if (length > bytes.size())
        fail("truncated GLB: its header says " + std::to_string(length) + " bytes, the file has " +
             std::to_string(bytes.size()));
    if (length < kGlbHeaderBytes + kChunkHeaderBytes) fail("GLB length " + std::to_string(length) + " is too short");
    const std::uint64_t jsonLength = readU32(bytes, 12);
    if (readU32(bytes, 16) != kJsonChunk) fail("the first GLB chunk is not JSON");
    const std::uint64_t jsonEnd = kGlbHeaderBytes + kChunkHeaderBytes + jsonLength;
    if (jsonLength == 0 || jsonEnd > length) fail("truncated GLB: the JSON chunk runs past the end of the file");
    checkJson(bytes.subspan(kGlbHeaderBytes + kChunkHeaderBytes, static_cast<std::size_t>(jsonLength)), notes);

    bool keepBin = false;
    if (length - jsonEnd >= kChunkHeaderBytes) {
        const std::uint64_t binLength = readU32(bytes, static_cast<std::size_t>(jsonEnd));
        if (readU32(bytes, static_cast<std::size_t>(jsonEnd) + 4) == kBinChunk) {
            if (jsonEnd + kChunkHeaderBytes + binLength > length)
                fail("truncated GLB: the BIN chunk runs past the end of the file");
            keepBin = true;
        }
    }
    if (keepBin) return bytes.first(length);
    // No BIN chunk, or one of an unknown type (which the spec says to skip): tinygltf rejects any
    // second chunk that is not BIN, so it gets the header and JSON alone.
    patched.assign(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(jsonEnd));
    const auto shortLength = static_cast<std::uint32_t>(jsonEnd);
    for (int i = 0; i < 4; ++i)
        patched[8 + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(shortLength >> (8 * i));
    return patched;
}

// Keeps images encoded; only the one base-colour texture used is decoded later, and only as PNG or
// JPEG. Images in buffer views are left alone: tinygltf 2.7 hands over their bytes without checking
// the view against its buffer, so they are read later through bufferViewBytes().
bool keepEncodedImage(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void* user) {
    if (image->bufferView >= 0 || bytes == nullptr || size <= 0) return true;
    (*static_cast<EncodedImages*>(user))[index].assign(bytes, bytes + size);
    return true;
}

// tinygltf's messages, several lines ending in newlines, as one line.
std::string oneLine(const std::string& text) {
    std::string line;
    for (const char c : text) {
        if (c == '\n' || c == '\r') {
            if (!line.empty() && line.back() != ' ') line += "; ";
        } else if (static_cast<unsigned char>(c) >= 0x20) {
            line += c;
        }
    }
    while (!line.empty() && (line.back() == ' ' || line.back() == ';')) line.pop_back();
    if (line.size() > 300) line = line.substr(0, 300) + "...";
    return line.empty() ? "tinygltf rejected it" : line;
}

}  // namespace

tinygltf::Model parseDocument(std::span<const std::uint8_t> bytes, const std::filesystem::path& baseDir,
                              const std::filesystem::path& assetRoot, EncodedImages& images,
                              std::vector<std::string>& notes) {
    if (bytes.empty()) fail("the file is empty");
    if (bytes.size() > kMaxGltfFileBytes) fail("the file is larger than 1 GiB");

    ExternalFiles files(baseDir, assetRoot);
    tinygltf::TinyGLTF parser;
    parser.SetFsCallbacks(files.callbacks());
    parser.SetImageLoader(&keepEncodedImage, &images);

    tinygltf::Model model;
    std::string error, warning;
    bool ok = false;
    try {
        if (bytes.size() >= 4 && readU32(bytes, 0) == kGlbMagic) {
            std::vector<std::uint8_t> patched;
            const std::span<const std::uint8_t> glb = checkGlb(bytes, patched, notes);
            ok = parser.LoadBinaryFromMemory(&model, &error, &warning, glb.data(),
                                             static_cast<unsigned int>(glb.size()), baseDir.string());
        } else {
            checkJson(bytes, notes);
            ok = parser.LoadASCIIFromString(&model, &error, &warning, reinterpret_cast<const char*>(bytes.data()),
                                            static_cast<unsigned int>(bytes.size()), baseDir.string());
        }
    } catch (const gpu::Error&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception& e) {
        fail(std::string("not a valid glTF file: ") + oneLine(e.what()));
    }
    // A refused URI fails the file even where tinygltf only warns (images): it is a file asking for
    // something it may not have, not one that is missing.
    if (!files.refusal().empty()) fail(oneLine(files.refusal()));
    if (!ok) fail("not a valid glTF file: " + oneLine(error));
    return model;
}

}  // namespace model::gltf
