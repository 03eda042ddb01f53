// The JSON types of the glTF properties, checked before tinygltf parses the document. tinygltf drops
// what it cannot parse: a node whose "children" holds an object loses all its children, a primitive
// whose "attributes" holds a string is left out of its mesh, an index of 2^32 becomes 0. Each would
// change the character without a word, so a property the loader reads with the wrong type is an
// error naming it; one the loader does not read (a camera, a sampler's filter, an accessor's min) is
// a note, since dropping it changes nothing.
#include <climits>

#include <nlohmann/json.hpp>

#include "model/gltf_internal.h"

namespace model::gltf {
namespace {

using nlohmann::json;

// What a JSON value must be, as the glTF 2.0 schema says.
enum class Type {
    Index,   // a whole number from 0 to INT_MAX (tinygltf keeps indices in an int)
    Size,    // a whole number from 0 (byte offsets, lengths, counts; tinygltf keeps them in a size_t)
    Number,
    String,
    Bool,
    Array,   // every element as `element`
    Object,  // `properties` as listed (others are not checked), and every value as `element` if given
};

// Whether the loader reads a property: a wrong type there is an error; elsewhere a note.
enum class Use { Read, Ignored };

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
    Use use = Use::Read;
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
constexpr Shape kAnyObject{Type::Object};
constexpr Shape kIndices{Type::Array, &kIndex};
constexpr Shape kNumbers{Type::Array, &kNumber};
constexpr Shape kStrings{Type::Array, &kString};
constexpr Shape kIndexByName{Type::Object, &kIndex};  // primitive attributes, morph targets

constexpr Use kIgnored = Use::Ignored;
// Every glTF object may have "extensions", an object; tinygltf skips one that is not.
constexpr Property kExtensions{"extensions", &kAnyObject, false, kIgnored};

constexpr Property kAsset[] = {{"version", &kString},
                               {"generator", &kString, false, kIgnored},
                               {"copyright", &kString, false, kIgnored},
                               {"minVersion", &kString, false, kIgnored},
                               kExtensions};
constexpr Property kBuffer[] = {{"byteLength", &kSize, true}, {"uri", &kString}, {"name", &kString}, kExtensions};
constexpr Property kBufferView[] = {{"buffer", &kIndex, true},
                                    {"byteLength", &kSize, true},
                                    {"byteOffset", &kSize},
                                    {"byteStride", &kSize},
                                    {"name", &kString},
                                    {"target", &kIndex, false, kIgnored},
                                    kExtensions};
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
                                  {"name", &kString},
                                  {"min", &kNumbers, false, kIgnored},
                                  {"max", &kNumbers, false, kIgnored},
                                  kExtensions};
constexpr Shape kTargets{Type::Array, &kIndexByName};
constexpr Property kPrimitive[] = {{"attributes", &kIndexByName, true},
                                   {"indices", &kIndex},
                                   {"material", &kIndex},
                                   {"mode", &kIndex},
                                   {"targets", &kTargets},
                                   kExtensions};
constexpr Shape kPrimitiveShape = objectOf(kPrimitive);
constexpr Shape kPrimitives{Type::Array, &kPrimitiveShape};
constexpr Property kMesh[] = {
    {"primitives", &kPrimitives, true}, {"name", &kString}, {"weights", &kNumbers, false, kIgnored}, kExtensions};
constexpr Property kNode[] = {{"name", &kString},
                              {"children", &kIndices},
                              {"mesh", &kIndex},
                              {"skin", &kIndex},
                              {"matrix", &kNumbers},
                              {"translation", &kNumbers},
                              {"rotation", &kNumbers},
                              {"scale", &kNumbers},
                              {"camera", &kIndex, false, kIgnored},
                              {"weights", &kNumbers, false, kIgnored},
                              kExtensions};
constexpr Property kSkin[] = {{"joints", &kIndices, true},
                              {"inverseBindMatrices", &kIndex},
                              {"name", &kString},
                              {"skeleton", &kIndex, false, kIgnored},
                              kExtensions};
// A target without a node is legal (an extension animates something else); see unanimatedChannels().
constexpr Property kTarget[] = {{"node", &kIndex}, {"path", &kString, true}, kExtensions};
constexpr Shape kTargetShape = objectOf(kTarget);
constexpr Property kChannel[] = {{"sampler", &kIndex, true}, {"target", &kTargetShape, true}, kExtensions};
constexpr Shape kChannelShape = objectOf(kChannel);
constexpr Shape kChannels{Type::Array, &kChannelShape};
constexpr Property kAnimationSampler[] = {
    {"input", &kIndex, true}, {"output", &kIndex, true}, {"interpolation", &kString}, kExtensions};
constexpr Shape kAnimationSamplerShape = objectOf(kAnimationSampler);
constexpr Shape kAnimationSamplers{Type::Array, &kAnimationSamplerShape};
constexpr Property kAnimation[] = {
    {"channels", &kChannels, true}, {"samplers", &kAnimationSamplers, true}, {"name", &kString}, kExtensions};
constexpr Property kTextureInfo[] = {{"index", &kIndex, true}, {"texCoord", &kIndex}, kExtensions};
constexpr Shape kTextureInfoShape = objectOf(kTextureInfo);
// Textures the loader does not use: normal, occlusion, emissive, metallic-roughness.
constexpr Property kOtherTextureInfo[] = {
    {"index", &kIndex, true}, {"texCoord", &kIndex}, {"scale", &kNumber}, {"strength", &kNumber}, kExtensions};
constexpr Shape kOtherTextureInfoShape = objectOf(kOtherTextureInfo);
constexpr Property kPbr[] = {{"baseColorFactor", &kNumbers},
                             {"baseColorTexture", &kTextureInfoShape},
                             {"metallicFactor", &kNumber, false, kIgnored},
                             {"roughnessFactor", &kNumber, false, kIgnored},
                             {"metallicRoughnessTexture", &kOtherTextureInfoShape, false, kIgnored},
                             kExtensions};
constexpr Shape kPbrShape = objectOf(kPbr);
constexpr Property kMaterial[] = {{"pbrMetallicRoughness", &kPbrShape},
                                  {"name", &kString},
                                  {"normalTexture", &kOtherTextureInfoShape, false, kIgnored},
                                  {"occlusionTexture", &kOtherTextureInfoShape, false, kIgnored},
                                  {"emissiveTexture", &kOtherTextureInfoShape, false, kIgnored},
                                  {"emissiveFactor", &kNumbers, false, kIgnored},
                                  {"alphaMode", &kString, false, kIgnored},
                                  {"alphaCutoff", &kNumber, false, kIgnored},
                                  {"doubleSided", &kBool, false, kIgnored},
                                  kExtensions};
constexpr Property kTexture[] = {
    {"source", &kIndex}, {"sampler", &kIndex, false, kIgnored}, {"name", &kString, false, kIgnored}, kExtensions};
constexpr Property kImage[] = {
    {"uri", &kString}, {"bufferView", &kIndex}, {"mimeType", &kString}, {"name", &kString}, kExtensions};
constexpr Property kScene[] = {{"nodes", &kIndices}, {"name", &kString}, kExtensions};
// What the loader does not read at all: texture samplers and cameras.
constexpr Property kSampler[] = {{"magFilter", &kIndex}, {"minFilter", &kIndex}, {"wrapS", &kIndex},
                                 {"wrapT", &kIndex},     {"name", &kString},     kExtensions};
constexpr Property kPerspective[] = {
    {"yfov", &kNumber, true}, {"znear", &kNumber, true}, {"aspectRatio", &kNumber}, {"zfar", &kNumber}};
constexpr Property kOrthographic[] = {
    {"xmag", &kNumber, true}, {"ymag", &kNumber, true}, {"zfar", &kNumber, true}, {"znear", &kNumber, true}};
constexpr Shape kPerspectiveShape = objectOf(kPerspective), kOrthographicShape = objectOf(kOrthographic);
constexpr Property kCamera[] = {{"type", &kString, true},
                                {"perspective", &kPerspectiveShape},
                                {"orthographic", &kOrthographicShape},
                                {"name", &kString},
                                kExtensions};

constexpr Shape kAssetShape = objectOf(kAsset);
constexpr Shape kBufferShape = objectOf(kBuffer), kBufferViewShape = objectOf(kBufferView),
                kAccessorShape = objectOf(kAccessor), kMeshShape = objectOf(kMesh), kNodeShape = objectOf(kNode),
                kSkinShape = objectOf(kSkin), kAnimationShape = objectOf(kAnimation),
                kMaterialShape = objectOf(kMaterial), kTextureShape = objectOf(kTexture),
                kImageShape = objectOf(kImage), kSceneShape = objectOf(kScene), kSamplerShape = objectOf(kSampler),
                kCameraShape = objectOf(kCamera);
constexpr Shape kBuffers{Type::Array, &kBufferShape}, kBufferViews{Type::Array, &kBufferViewShape},
                kAccessors{Type::Array, &kAccessorShape}, kMeshes{Type::Array, &kMeshShape},
                kNodes{Type::Array, &kNodeShape}, kSkins{Type::Array, &kSkinShape},
                kAnimations{Type::Array, &kAnimationShape}, kMaterials{Type::Array, &kMaterialShape},
                kTextures{Type::Array, &kTextureShape}, kImages{Type::Array, &kImageShape},
                kScenes{Type::Array, &kSceneShape}, kSamplers{Type::Array, &kSamplerShape},
                kCameras{Type::Array, &kCameraShape};
constexpr Property kDocument[] = {{"asset", &kAssetShape},
                                  {"extensionsRequired", &kStrings},
                                  {"extensionsUsed", &kStrings, false, kIgnored},
                                  {"buffers", &kBuffers},
                                  {"bufferViews", &kBufferViews},
                                  {"accessors", &kAccessors},
                                  {"meshes", &kMeshes},
                                  {"nodes", &kNodes},
                                  {"skins", &kSkins},
                                  {"animations", &kAnimations},
                                  {"materials", &kMaterials},
                                  {"textures", &kTextures},
                                  {"images", &kImages},
                                  {"scenes", &kScenes},
                                  {"scene", &kIndex},
                                  {"samplers", &kSamplers, false, kIgnored},
                                  {"cameras", &kCameras, false, kIgnored},
                                  kExtensions};
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

// The value as a message shows it: numbers and booleans as written, other values by their kind (a
// string's text may be anything, and long).
std::string found(const json& value) {
    if (value.is_number() || value.is_boolean()) return value.dump();
    if (value.is_null()) return "null";
    if (value.is_string()) return "a string";
    if (value.is_array()) return "an array";
    return "an object";
}

std::string member(const std::string& path, const std::string& name) { return path.empty() ? name : path + "." + name; }

std::string named(const std::string& path) { return path.empty() ? std::string("the document") : path; }

// Walks the document against the schema: the first problem in what the loader reads fails; problems
// in what it ignores are counted, the first kept for a note.
class Checker {
public:
    void check(const json& value, const Shape& shape, const std::string& path, Use use) {
        if (!matches(value, shape.type))
            return problem(use, named(path) + ": expected " + expected(shape.type) + ", found " + found(value));
        if (shape.type == Type::Array) {
            for (std::size_t i = 0; i < value.size(); ++i)
                check(value[i], *shape.element, path + "[" + std::to_string(i) + "]", use);
        } else if (shape.type == Type::Object) {
            if (shape.element)
                for (auto item = value.begin(); item != value.end(); ++item)
                    check(item.value(), *shape.element, member(path, item.key()), use);
            for (std::size_t p = 0; p < shape.propertyCount; ++p) {
                const Property& property = shape.properties[p];
                const Use inner = use == Use::Ignored ? Use::Ignored : property.use;
                if (const auto item = value.find(property.name); item != value.end())
                    check(*item, *property.shape, member(path, property.name), inner);
                else if (property.required)
                    problem(inner, named(path) + ": " + property.name + " is missing");
            }
        }
    }

    void addNote(std::vector<std::string>& notes) const {
        if (ignored_ == 0) return;
        notes.push_back(firstIgnored_ + (ignored_ > 1 ? " (and " + std::to_string(ignored_ - 1) + " more)" : "") +
                        "; ignored: the loader does not use it");
    }

private:
    void problem(Use use, const std::string& message) {
        if (use == Use::Read) fail(message);
        if (ignored_++ == 0) firstIgnored_ = message;
    }

    std::size_t ignored_ = 0;
    std::string firstIgnored_;
};

// Channels whose target names no node animate what an extension defines; tinygltf drops them.
std::size_t unanimatedChannels(const json& document) {
    std::size_t count = 0;
    const auto animations = document.find("animations");
    if (animations == document.end()) return 0;
    // The checker has made sure every animation has channels and every channel a target.
    for (const json& animation : *animations)
        for (const json& channel : animation.at("channels"))
            if (!channel.at("target").contains("node")) ++count;
    return count;
}

// Each animation's "extras.events" (docs/events.md), which the loader reads (gltf_animation.cpp): its
// types are checked here, on the JSON as written, because tinygltf drops null, [] and {} from extras, so
// "events": null, or an event that is null or {}, would vanish before the loader sees it. Anything else
// in extras, and extras that are not an object, are the file's own business. What the values mean (a
// time within the clip, a joint of the skeleton) the loader checks.
void checkClipEvents(const json& document) {
    const auto animations = document.find("animations");
    if (animations == document.end()) return;
    // The checker has made sure "animations" is an array of objects.
    for (std::size_t a = 0; a < animations->size(); ++a) {
        const json& animation = (*animations)[a];
        const auto extras = animation.find("extras");
        if (extras == animation.end() || !extras->is_object()) continue;
        const auto events = extras->find("events");
        if (events == extras->end()) continue;
        const std::string field = "animations[" + std::to_string(a) + "].extras.events";
        if (!events->is_array())
            fail(field + ": expected an array of {\"name\": string, \"time\": seconds}, found " + found(*events));
        for (std::size_t e = 0; e < events->size(); ++e) {
            const json& event = (*events)[e];
            const std::string at = field + "[" + std::to_string(e) + "]";
            if (!event.is_object())
                fail(at + ": expected an object {\"name\": string, \"time\": seconds}, found " + found(event));
            const auto name = event.find("name");
            if (name == event.end() || !name->is_string() || name->get<std::string>().empty())
                fail(at + ".name: expected a non-empty string, found " + (name == event.end() ? "none" : found(*name)));
            const auto time = event.find("time");
            if (time == event.end() || !time->is_number())
                fail(at + ".time: expected a number of seconds, found " + (time == event.end() ? "none" : found(*time)));
            const auto joint = event.find("joint");
            if (joint != event.end() && !joint->is_string())
                fail(at + ".joint: expected the name of a joint (a string), found " + found(*joint));
        }
    }
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
    Checker checker;
    checker.check(document, kDocumentShape, "", Use::Read);
    checkClipEvents(document);
    checker.addNote(notes);
    if (const std::size_t channels = unanimatedChannels(document); channels > 0)
        notes.push_back(std::to_string(channels) + " animation channel(s) without a target node ignored");
}

}  // namespace model::gltf
