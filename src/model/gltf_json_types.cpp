// The JSON types of every glTF property the loader reads, checked before tinygltf parses the document.
// tinygltf drops what it cannot parse: a node whose "children" holds an object loses all its children,
// a primitive whose "attributes" holds a string is left out of its mesh, an index of 2^32 becomes 0.
// Each would change the character without a word, so each is an error naming the property.
#include <climits>

#include <nlohmann/json.hpp>

#include "model/gltf_internal.h"

namespace model::gltf {
namespace {

using nlohmann::json;

// What a JSON value must be, as the glTF 2.0 schema says for the properties the loader reads.
enum class Type {
    Index,   // a whole number from 0 to INT_MAX (tinygltf keeps indices in an int)
    Size,    // a whole number from 0 (byte offsets, lengths, counts; tinygltf keeps them in a size_t)
    Number,
    String,
    Bool,
    Array,   // every element as `element`
    Object,  // `properties` as listed (others are not checked), and every value as `element` if given
};

struct Property;

struct Shape {
    Type type;
    const Shape* element = nullptr;
    const Property* properties = nullptr;
    std::size_t propertyCount = 0;
};

struct Property {
    const char* name;
    const Shape* shape;
    bool required = false;
};

template <std::size_t N>
constexpr Shape objectOf(const Property (&properties)[N]) {
    return {Type::Object, nullptr, properties, N};
}

constexpr Shape kIndex{Type::Index};
constexpr Shape kSize{Type::Size};
constexpr Shape kNumber{Type::Number};
constexpr Shape kString{Type::String};
constexpr Shape kBool{Type::Bool};
constexpr Shape kIndices{Type::Array, &kIndex};
constexpr Shape kNumbers{Type::Array, &kNumber};
constexpr Shape kStrings{Type::Array, &kString};
constexpr Shape kIndexByName{Type::Object, &kIndex};  // primitive attributes, morph targets

constexpr Property kAsset[] = {{"version", &kString}};
constexpr Property kBuffer[] = {{"byteLength", &kSize, true}, {"uri", &kString}, {"name", &kString}};
constexpr Property kBufferView[] = {{"buffer", &kIndex, true},
                                    {"byteLength", &kSize, true},
                                    {"byteOffset", &kSize},
                                    {"byteStride", &kSize},
                                    {"name", &kString}};
constexpr Property kSparseIndices[] = {
    {"bufferView", &kIndex, true}, {"byteOffset", &kIndex}, {"componentType", &kIndex, true}};
constexpr Property kSparseValues[] = {{"bufferView", &kIndex, true}, {"byteOffset", &kIndex}};
constexpr Shape kSparseIndicesShape = objectOf(kSparseIndices);
constexpr Shape kSparseValuesShape = objectOf(kSparseValues);
constexpr Property kSparse[] = {
    {"count", &kIndex, true}, {"indices", &kSparseIndicesShape, true}, {"values", &kSparseValuesShape, true}};
constexpr Shape kSparseShape = objectOf(kSparse);
constexpr Property kAccessor[] = {{"componentType", &kSize, true},
                                  {"count", &kSize, true},
                                  {"type", &kString, true},
                                  {"bufferView", &kIndex},
                                  {"byteOffset", &kSize},
                                  {"normalized", &kBool},
                                  {"sparse", &kSparseShape},
                                  {"name", &kString}};
constexpr Shape kTargets{Type::Array, &kIndexByName};
constexpr Property kPrimitive[] = {{"attributes", &kIndexByName, true},
                                   {"indices", &kIndex},
                                   {"material", &kIndex},
                                   {"mode", &kIndex},
                                   {"targets", &kTargets}};
constexpr Shape kPrimitiveShape = objectOf(kPrimitive);
constexpr Shape kPrimitives{Type::Array, &kPrimitiveShape};
constexpr Property kMesh[] = {{"primitives", &kPrimitives, true}, {"name", &kString}};
constexpr Property kNode[] = {{"name", &kString},        {"children", &kIndices},    {"mesh", &kIndex},
                              {"skin", &kIndex},         {"matrix", &kNumbers},      {"translation", &kNumbers},
                              {"rotation", &kNumbers},   {"scale", &kNumbers}};
constexpr Property kSkin[] = {{"joints", &kIndices, true}, {"inverseBindMatrices", &kIndex}, {"name", &kString}};
// A target without a node is legal (an extension animates something else); see unanimatedChannels().
constexpr Property kTarget[] = {{"node", &kIndex}, {"path", &kString, true}};
constexpr Shape kTargetShape = objectOf(kTarget);
constexpr Property kChannel[] = {{"sampler", &kIndex, true}, {"target", &kTargetShape, true}};
constexpr Shape kChannelShape = objectOf(kChannel);
constexpr Shape kChannels{Type::Array, &kChannelShape};
constexpr Property kSampler[] = {{"input", &kIndex, true}, {"output", &kIndex, true}, {"interpolation", &kString}};
constexpr Shape kSamplerShape = objectOf(kSampler);
constexpr Shape kSamplers{Type::Array, &kSamplerShape};
constexpr Property kAnimation[] = {{"channels", &kChannels, true}, {"samplers", &kSamplers, true}, {"name", &kString}};
constexpr Property kTextureInfo[] = {{"index", &kIndex, true}, {"texCoord", &kIndex}};
constexpr Shape kTextureInfoShape = objectOf(kTextureInfo);
constexpr Property kPbr[] = {{"baseColorFactor", &kNumbers}, {"baseColorTexture", &kTextureInfoShape}};
constexpr Shape kPbrShape = objectOf(kPbr);
constexpr Property kMaterial[] = {{"pbrMetallicRoughness", &kPbrShape}, {"name", &kString}};
constexpr Property kTexture[] = {{"source", &kIndex}};
constexpr Property kImage[] = {{"uri", &kString}, {"bufferView", &kIndex}, {"mimeType", &kString}, {"name", &kString}};
constexpr Property kScene[] = {{"nodes", &kIndices}, {"name", &kString}};

constexpr Shape kAssetShape = objectOf(kAsset);
constexpr Shape kBufferShape = objectOf(kBuffer), kBufferViewShape = objectOf(kBufferView),
                kAccessorShape = objectOf(kAccessor), kMeshShape = objectOf(kMesh), kNodeShape = objectOf(kNode),
                kSkinShape = objectOf(kSkin), kAnimationShape = objectOf(kAnimation),
                kMaterialShape = objectOf(kMaterial), kTextureShape = objectOf(kTexture),
                kImageShape = objectOf(kImage), kSceneShape = objectOf(kScene);
constexpr Shape kBuffers{Type::Array, &kBufferShape}, kBufferViews{Type::Array, &kBufferViewShape},
                kAccessors{Type::Array, &kAccessorShape}, kMeshes{Type::Array, &kMeshShape},
                kNodes{Type::Array, &kNodeShape}, kSkins{Type::Array, &kSkinShape},
                kAnimations{Type::Array, &kAnimationShape}, kMaterials{Type::Array, &kMaterialShape},
                kTextures{Type::Array, &kTextureShape}, kImages{Type::Array, &kImageShape},
                kScenes{Type::Array, &kSceneShape};
constexpr Property kDocument[] = {
    {"asset", &kAssetShape},   {"extensionsRequired", &kStrings}, {"extensionsUsed", &kStrings},
    {"buffers", &kBuffers},    {"bufferViews", &kBufferViews},    {"accessors", &kAccessors},
    {"meshes", &kMeshes},      {"nodes", &kNodes},                {"skins", &kSkins},
    {"animations", &kAnimations}, {"materials", &kMaterials},     {"textures", &kTextures},
    {"images", &kImages},      {"scenes", &kScenes},              {"scene", &kIndex}};
constexpr Shape kDocumentShape = objectOf(kDocument);

bool isIndex(const json& value) {
    if (value.is_number_unsigned()) return value.get<std::uint64_t>() <= INT_MAX;
    return value.is_number_integer() && value.get<std::int64_t>() >= 0 && value.get<std::int64_t>() <= INT_MAX;
}

bool matches(const json& value, Type type) {
    switch (type) {
        case Type::Index: return isIndex(value);
        case Type::Size: return value.is_number_unsigned();
        case Type::Number: return value.is_number();
        case Type::String: return value.is_string();
        case Type::Bool: return value.is_boolean();
        case Type::Array: return value.is_array();
        case Type::Object: return value.is_object();
    }
    return false;
}

const char* expected(Type type) {
    switch (type) {
        case Type::Index: return "an index (a whole number from 0 to 2147483647)";
        case Type::Size: return "a whole number from 0";
        case Type::Number: return "a number";
        case Type::String: return "a string";
        case Type::Bool: return "true or false";
        case Type::Array: return "an array";
        case Type::Object: return "an object";
    }
    return "";
}

// The value as a message shows it: numbers as written, other values by their kind (a string's text
// may be anything, and long).
std::string found(const json& value) {
    if (value.is_number()) return value.dump();
    if (value.is_boolean()) return value.dump();
    if (value.is_null()) return "null";
    if (value.is_string()) return "a string";
    if (value.is_array()) return "an array";
    return "an object";
}

std::string member(const std::string& path, const std::string& name) { return path.empty() ? name : path + "." + name; }

void check(const json& value, const Shape& shape, const std::string& path) {
    if (!matches(value, shape.type))
        fail((path.empty() ? std::string("the document") : path) + ": expected " + expected(shape.type) + ", found " +
             found(value));
    if (shape.type == Type::Array) {
        for (std::size_t i = 0; i < value.size(); ++i)
            check(value[i], *shape.element, path + "[" + std::to_string(i) + "]");
    } else if (shape.type == Type::Object) {
        if (shape.element)
            for (auto item = value.begin(); item != value.end(); ++item)
                check(item.value(), *shape.element, member(path, item.key()));
        for (std::size_t p = 0; p < shape.propertyCount; ++p) {
            const Property& property = shape.properties[p];
            const auto item = value.find(property.name);
            if (item != value.end())
                check(*item, *property.shape, member(path, property.name));
            else if (property.required)
                fail((path.empty() ? std::string("the document") : path) + ": " + property.name + " is missing");
        }
    }
}

// Channels whose target names no node animate what an extension defines; tinygltf drops them.
std::size_t unanimatedChannels(const json& document) {
    std::size_t count = 0;
    const auto animations = document.find("animations");
    if (animations == document.end()) return 0;
    // check() has made sure every animation has channels and every channel a target.
    for (const json& animation : *animations)
        for (const json& channel : animation.at("channels"))
            if (!channel.at("target").contains("node")) ++count;
    return count;
}

}  // namespace

void checkJsonTypes(std::span<const std::uint8_t> text, std::vector<std::string>& notes) {
    json document;
    try {
        document = json::parse(text.begin(), text.end());
    } catch (const json::exception& error) {
        fail(std::string("not a valid glTF file: ") + error.what());
    }
    if (!document.is_object()) fail("not a valid glTF file: the JSON is not an object");
    check(document, kDocumentShape, "");
    if (const std::size_t channels = unanimatedChannels(document); channels > 0)
        notes.push_back(std::to_string(channels) + " animation channel(s) without a target node ignored");
}

}  // namespace model::gltf
