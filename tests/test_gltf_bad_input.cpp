// Malformed glTF files: each gives one gpu::Error naming the file and the problem, never a crash or
// a hang. Hand-made cases for each kind of damage, every prefix of a GLB, and assimp's corpus of
// deliberately broken files.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>

#include <gtest/gtest.h>
#include <unistd.h>

#include "gpu/vulkan_error.h"
#include "model/gltf_loader.h"
#include "support/gltf_builder.h"
#include "support/run_program.h"

namespace {

using test::GltfBuilder;

// Loading fails with one line that starts with the file's name and mentions `mention`.
void expectError(const std::vector<std::uint8_t>& bytes, const std::string& mention) {
    try {
        test::loadBytes(bytes);
        ADD_FAILURE() << "loaded; expected an error mentioning '" << mention << "'";
    } catch (const gpu::Error& error) {
        const std::string message = error.what();
        EXPECT_EQ(message.rfind("test.gltf: ", 0), 0u) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        EXPECT_NE(message.find(mention), std::string::npos) << message;
    }
}

void expectError(const std::string& text, const std::string& mention) {
    expectError(std::vector<std::uint8_t>(text.begin(), text.end()), mention);
}

// Loads, or fails with gpu::Error; anything else fails the test (a crash fails the whole binary).
bool loadsOrFailsCleanly(const std::vector<std::uint8_t>& bytes) {
    try {
        test::loadBytes(bytes);
        return true;
    } catch (const gpu::Error&) {
        return false;
    }
}

}  // namespace

TEST(GltfBadInput, EmptyFile) { expectError(std::string(), "empty"); }

TEST(GltfBadInput, EveryTruncationOfAGlbFailsCleanly) {
    const std::vector<std::uint8_t> glb = test::stripCharacter().glb();
    for (std::size_t size = 1; size < glb.size(); ++size) {
        const std::vector<std::uint8_t> prefix(glb.begin(), glb.begin() + static_cast<std::ptrdiff_t>(size));
        EXPECT_THROW(test::loadBytes(prefix), gpu::Error) << size << " of " << glb.size() << " bytes";
    }
    expectError(std::vector<std::uint8_t>(glb.begin(), glb.begin() + 100), "truncated GLB");
}

TEST(GltfBadInput, TruncatedJsonFailsCleanly) {
    const std::string text = test::stripCharacter().gltf();
    for (std::size_t size = 1; size < text.size(); size += 97)
        EXPECT_THROW(test::loadText(text.substr(0, size)), gpu::Error) << size << " of " << text.size() << " bytes";
    expectError(text.substr(0, text.size() / 2), "not a valid glTF file");
}

TEST(GltfBadInput, GlbHeaderProblemsAreNamed) {
    std::vector<std::uint8_t> glb = test::stripCharacter().glb();
    std::vector<std::uint8_t> bad = glb;
    bad[4] = 1;  // version 1
    expectError(bad, "GLB version 1");
    bad = glb;
    bad[12] = 0xFF, bad[13] = 0xFF;  // JSON chunk longer than the file
    expectError(bad, "JSON chunk runs past the end");
    bad = glb;
    bad[8] = 0xFF, bad[9] = 0xFF, bad[10] = 0xFF;  // header length beyond the file
    expectError(bad, "truncated GLB");
}

TEST(GltfBadInput, WrongJsonTypesFailCleanly) {
    const nlohmann::json good = nlohmann::json::parse(test::stripCharacter().gltf());
    // Replace each top-level array, and each member of the first element of each array, by values
    // of every other JSON type.
    const std::vector<nlohmann::json> wrong = {
        5, -1, 1e300, "text", nlohmann::json::array(), nlohmann::json::object(), nullptr, true, {1, 2, 3}};
    int loaded = 0, failed = 0;
    for (auto top = good.begin(); top != good.end(); ++top) {
        for (const nlohmann::json& value : wrong) {
            nlohmann::json doc = good;
            doc[top.key()] = value;
            const std::string text = doc.dump();
            (loadsOrFailsCleanly(std::vector<std::uint8_t>(text.begin(), text.end())) ? loaded : failed)++;
        }
        if (!top.value().is_array() || top.value().empty() || !top.value()[0].is_object()) continue;
        for (auto member = top.value()[0].begin(); member != top.value()[0].end(); ++member) {
            for (const nlohmann::json& value : wrong) {
                nlohmann::json doc = good;
                doc[top.key()][0][member.key()] = value;
                const std::string text = doc.dump();
                (loadsOrFailsCleanly(std::vector<std::uint8_t>(text.begin(), text.end())) ? loaded : failed)++;
            }
        }
    }
    EXPECT_GT(failed, 0);
    expectError(R"({"asset": {"version": "2.0"}, "nodes": 5})", "nodes: expected an array, found 5");
    expectError(R"([1, 2, 3])", "not a valid glTF file");
}

TEST(GltfBadInput, ChildrenHoldingAnObjectIsAnErrorNotASmallerSkeleton) {
    // tinygltf drops a "children" array it cannot read whole: the strip's root would lose its tip
    // joint and load as a one-bone character.
    GltfBuilder b = test::stripCharacter();
    b.doc["nodes"][1]["children"] = {nlohmann::json::object()};
    expectError(b.gltf(), "test.gltf: nodes[1].children[0]: expected an index (a whole number from 0 to 2147483647), "
                          "found an object");
    expectError(b.glb(), "nodes[1].children[0]: expected an index");
}

namespace {

// "/nodes/0/children" as the loader names it: "nodes[0].children".
std::string propertyPath(const std::string& pointer) {
    std::string path;
    std::size_t start = 1;
    while (start <= pointer.size()) {
        const std::size_t end = std::min(pointer.find('/', start), pointer.size());
        const std::string token = pointer.substr(start, end - start);
        const bool index = !token.empty() && token.find_first_not_of("0123456789") == std::string::npos;
        path += index ? "[" + token + "]" : (path.empty() ? "" : ".") + token;
        start = end + 1;
    }
    return path;
}

}  // namespace

TEST(GltfBadInput, EveryPropertyTheLoaderReadsMustHaveItsSchemaType) {
    using nlohmann::json;
    // Values of every other JSON type for each kind of property. Indices must also fit tinygltf's int
    // (4294967296 would become 0) and be whole and not negative, as sizes must.
    const std::map<std::string, std::vector<json>> wrong = {
        {"index", {"0", 1.5, -1, 4294967296ull, true, nullptr, json::array(), json::object()}},
        {"size", {"0", 1.5, -1, true, nullptr, json::array(), json::object()}},
        {"string", {5, true, nullptr, json::array(), json::object()}},
        {"indices", {5, "0", json::object(), {1.5}, {json::object()}, {"0"}, {-1}}},
        {"numbers", {5, "0", json::object(), {"1"}, {nullptr}, {json::object()}}},
        {"object", {5, "x", true, nullptr, json::array()}},
        {"objects", {5, "x", json::object(), {5}, {"x"}}},
    };
    const std::vector<std::pair<std::string, std::string>> properties = {
        {"/scene", "index"},
        {"/scenes/0/nodes", "indices"},
        {"/nodes", "objects"},
        {"/nodes/0/children", "indices"},
        {"/nodes/0/translation", "numbers"},
        {"/nodes/1/name", "string"},
        {"/nodes/3/mesh", "index"},
        {"/nodes/3/skin", "index"},
        {"/skins/0/joints", "indices"},
        {"/skins/0/inverseBindMatrices", "index"},
        {"/meshes/0/primitives", "objects"},
        {"/meshes/0/primitives/0/attributes", "object"},
        {"/meshes/0/primitives/0/attributes/POSITION", "index"},
        {"/meshes/0/primitives/0/indices", "index"},
        {"/meshes/0/primitives/0/material", "index"},
        {"/materials/0/pbrMetallicRoughness", "object"},
        {"/materials/0/pbrMetallicRoughness/baseColorFactor", "numbers"},
        {"/accessors/0/bufferView", "index"},
        {"/accessors/0/componentType", "size"},
        {"/accessors/0/count", "size"},
        {"/accessors/0/type", "string"},
        {"/bufferViews/0/buffer", "index"},
        {"/bufferViews/0/byteOffset", "size"},
        {"/bufferViews/0/byteLength", "size"},
        {"/buffers/0/byteLength", "size"},
        {"/buffers/0/uri", "string"},
        {"/animations/0/name", "string"},
        {"/animations/0/channels/0/sampler", "index"},
        {"/animations/0/channels/0/target", "object"},
        {"/animations/0/channels/0/target/node", "index"},
        {"/animations/0/channels/0/target/path", "string"},
        {"/animations/0/samplers/0/input", "index"},
        {"/animations/0/samplers/0/output", "index"},
        {"/animations/0/samplers/0/interpolation", "string"},
    };
    GltfBuilder strip = test::stripCharacter();
    strip.doc["buffers"] = {{{"byteLength", strip.bin.size()},
                             {"uri", "data:application/octet-stream;base64," + test::base64(strip.bin)}}};
    for (const auto& [pointer, kind] : properties) {
        ASSERT_TRUE(strip.doc.contains(json::json_pointer(pointer))) << pointer;
        for (const json& value : wrong.at(kind)) {
            SCOPED_TRACE(pointer + " = " + value.dump());
            GltfBuilder b = strip;
            b.doc[json::json_pointer(pointer)] = value;
            // The property, or the element of it, that has the wrong type.
            expectError(b.gltf(false), "test.gltf: " + propertyPath(pointer));
            expectError(b.gltf(false), ": expected ");
        }
    }
}

TEST(GltfBadInput, WrongTypesWhereTheLoaderReadsNothingGiveOneNote) {
    // tinygltf drops these too, but the character does not change: a note, not an error.
    GltfBuilder b = test::stripCharacter();
    b.doc["accessors"][0]["min"] = "lowest";
    b.doc["nodes"][0]["camera"] = "main";
    b.doc["samplers"] = {{{"wrapS", "repeat"}}};
    b.doc["materials"][0]["normalTexture"] = {{"index", -1}};
    std::vector<std::string> notes;
    const model::SkinnedModel m = test::loadText(b.gltf(), &notes);
    EXPECT_EQ(m.triangleCount(), 4u);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(notes[0], "test.gltf: accessors[0].min: expected an array, found a string (and 3 more); ignored: the "
                        "loader does not use it");
}

TEST(GltfBadInput, MissingRequiredPropertiesAreNamed) {
    // tinygltf leaves out a primitive without attributes and a channel without a sampler: the mesh or
    // clip would silently lose them.
    GltfBuilder b = test::stripCharacter();
    test::stripPrimitive(b).erase("attributes");
    expectError(b.gltf(), "meshes[0].primitives[0]: attributes is missing");
    b = test::stripCharacter();
    b.doc["animations"][0]["channels"][0].erase("sampler");
    expectError(b.gltf(), "animations[0].channels[0]: sampler is missing");
}

TEST(GltfBadInput, ChannelWithoutATargetNodeIsIgnoredWithANote) {
    // Legal glTF (an extension names what it animates); the loader can ignore it, and says so.
    GltfBuilder b = test::stripCharacter();
    b.doc["animations"][0]["channels"].push_back({{"sampler", 0}, {"target", {{"path", "rotation"}}}});
    std::vector<std::string> notes;
    const model::SkinnedModel m = test::loadText(b.gltf(), &notes);
    ASSERT_EQ(m.clips.size(), 1u);
    EXPECT_EQ(m.clips[0].channels.size(), 1u);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(notes[0], "test.gltf: 1 animation channel(s) without a target node ignored");
}

TEST(GltfBadInput, AccessorIndexOutOfRange) {
    GltfBuilder b = test::stripCharacter();
    test::stripPrimitive(b)["attributes"]["POSITION"] = 99;
    expectError(b.gltf(), "mesh 0 primitive 0 POSITION: accessor 99 does not exist");
}

TEST(GltfBadInput, AccessorPastTheEndOfItsBufferView) {
    GltfBuilder b = test::stripCharacter();
    const int positions = test::stripPrimitive(b)["attributes"]["POSITION"];
    b.doc["accessors"][static_cast<std::size_t>(positions)]["count"] = 7;
    expectError(b.gltf(), "runs past the end of buffer view");
    b.doc["accessors"][static_cast<std::size_t>(positions)]["count"] = 6;
    b.doc["accessors"][static_cast<std::size_t>(positions)]["byteOffset"] = 4;
    expectError(b.gltf(), "runs past the end of buffer view");
    // A count so large that offset + count * stride would overflow 64 bits.
    b.doc["accessors"][static_cast<std::size_t>(positions)]["byteOffset"] = 0;
    b.doc["accessors"][static_cast<std::size_t>(positions)]["count"] = 1537228672809129301ull;
    expectError(b.gltf(), "POSITION: accessor");
}

TEST(GltfBadInput, AccessorOfTheWrongType) {
    GltfBuilder b = test::stripCharacter();
    test::stripPrimitive(b)["attributes"]["JOINTS_0"] = test::stripPrimitive(b)["attributes"]["WEIGHTS_0"];
    expectError(b.gltf(), "JOINTS_0: accessor 3 holds VEC4 of float; expected VEC4 of unsigned byte or unsigned short");
}

TEST(GltfBadInput, BufferViewPastTheEndOfItsBuffer) {
    GltfBuilder b = test::stripCharacter();
    b.doc["bufferViews"][0]["byteLength"] = 100000;
    expectError(b.gltf(), "runs past the end of buffer 0");
    b = test::stripCharacter();
    b.doc["bufferViews"][0]["buffer"] = 3;
    expectError(b.gltf(), "buffer 3, which does not exist");
    b = test::stripCharacter();
    b.doc["bufferViews"][0]["byteStride"] = 8;  // smaller than a VEC3 of floats
    expectError(b.gltf(), "byte stride 8 is smaller than its elements");
}

TEST(GltfBadInput, MissingOrShortBuffers) {
    GltfBuilder b = test::stripCharacter();
    b.doc["buffers"] = {
        {{"byteLength", b.bin.size() + 4}, {"uri", "data:application/octet-stream;base64," + test::base64(b.bin)}}};
    expectError(b.gltf(false), "not a valid glTF file");  // data shorter than byteLength
    b.doc["buffers"] = {{{"byteLength", b.bin.size()}, {"uri", "missing.bin"}}};
    expectError(b.gltf(false), "missing.bin");  // no external files from memory
    b.doc.erase("buffers");
    expectError(b.gltf(false), "buffer 0, which does not exist");

    // From a file: a missing and a short external buffer.
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("crowd-gltf-bad-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    b.doc["buffers"] = {{{"byteLength", b.bin.size()}, {"uri", "strip.bin"}}};
    std::ofstream(dir / "strip.gltf") << b.gltf(false);
    EXPECT_THROW(model::loadGltf(dir / "strip.gltf"), gpu::Error);
    std::ofstream(dir / "strip.bin", std::ios::binary).write(reinterpret_cast<const char*>(b.bin.data()), 16);
    try {
        model::loadGltf(dir / "strip.gltf");
        ADD_FAILURE() << "a 16-byte buffer file loaded";
    } catch (const gpu::Error& error) {
        EXPECT_NE(std::string(error.what()).find((dir / "strip.gltf").string()), std::string::npos) << error.what();
    }
    EXPECT_THROW(model::loadGltf(dir / "absent.glb"), gpu::Error);
    EXPECT_THROW(model::loadGltf(dir), gpu::Error);  // a directory
    std::filesystem::remove_all(dir);
}

TEST(GltfBadInput, CyclicNodeGraphs) {
    GltfBuilder b = test::stripCharacter();
    b.doc["nodes"][2]["children"] = {1};   // tip -> root -> tip
    expectError(b.gltf(), "two parents");  // root has parents world and tip
    b.doc["nodes"][0]["children"] = {3};
    expectError(b.gltf(), "cycle");  // root <-> tip, reachable from nowhere
    b = test::stripCharacter();
    b.doc["nodes"][2]["children"] = {2};
    expectError(b.gltf(), "node 2 is its own child");
    b = test::stripCharacter();
    b.doc["nodes"][2]["children"] = {7};
    expectError(b.gltf(), "lists child 7, which does not exist");
}

TEST(GltfBadInput, NoSkin) {
    GltfBuilder b = test::stripCharacter();
    b.doc["nodes"][3].erase("skin");
    expectError(b.gltf(), "no skinned mesh: no node has both a mesh and a skin");
    b.doc["nodes"][3].erase("mesh");
    expectError(b.gltf(), "no skinned mesh");
    b = test::stripCharacter();
    b.doc["nodes"][3]["skin"] = 4;
    expectError(b.gltf(), "skin 4, which does not exist");
    b = test::stripCharacter();
    b.doc["skins"][0]["joints"] = nlohmann::json::array();
    expectError(b.gltf(), "skin 0 has no joints");
}

TEST(GltfBadInput, MoreJointsThanSupported) {
    GltfBuilder b = test::stripCharacter();
    nlohmann::json joints = {1, 2};
    for (int i = 0; i < 300; ++i) {
        b.doc["nodes"][2]["children"].push_back(b.doc["nodes"].size());
        joints.push_back(b.doc["nodes"].size());
        b.doc["nodes"].push_back({{"name", "extra"}});
    }
    b.doc["skins"][0]["joints"] = joints;
    b.doc["skins"][0].erase("inverseBindMatrices");
    expectError(b.gltf(), "302 joints (at most 256 are supported)");
}

TEST(GltfBadInput, NaNNegativeAndInfiniteValues) {
    GltfBuilder b = test::stripCharacter();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    test::stripPrimitive(b)["attributes"]["WEIGHTS_0"] = b.floats({nan,  0,    0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0,  //
                                                                   0.5f, 0.5f, 0, 0, 1, 0, 0, 0, 1,    0,    0, 0},
                                                                  "VEC4");
    expectError(b.gltf(), "WEIGHTS_0: accessor 8 element 0 is not a finite number");
    test::stripPrimitive(b)["attributes"]["WEIGHTS_0"] = b.floats({1.5f, -0.5f, 0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0,  //
                                                                   0.5f, 0.5f,  0, 0, 1, 0, 0, 0, 1,    0,    0, 0},
                                                                  "VEC4");
    expectError(b.gltf(), "vertex 0 has a negative weight");
    b = test::stripCharacter();
    b.doc["nodes"][1]["translation"] = {0, 1e300, 0};
    expectError(b.gltf(), "node 1 translation is not a finite number");
    b = test::stripCharacter();
    b.doc["nodes"][1]["rotation"] = {0, 0, 0, 0};
    expectError(b.gltf(), "node 1: rotation is not a unit quaternion");
    b = test::stripCharacter();
    b.doc["nodes"][1]["scale"] = {1e30, 1e30, 1e30};
    b.doc["nodes"][2]["scale"] = {1e30, 1e30, 1e30};
    expectError(b.gltf(), "the rest pose can put vertices ");
}

TEST(GltfBadInput, VertexIndicesAndJointNumbersOutOfRange) {
    GltfBuilder b = test::stripCharacter();
    test::stripPrimitive(b)["indices"] = b.shorts({0, 1, 3, 0, 3, 6}, "SCALAR");
    expectError(b.gltf(), "index 5 is vertex 6, beyond its 6 vertices");
    test::stripPrimitive(b)["indices"] = b.shorts({0, 1, 3, 0}, "SCALAR");
    expectError(b.gltf(), "4 indices is not a whole number of triangles");
    b = test::stripCharacter();
    test::stripPrimitive(b)["attributes"]["JOINTS_0"] =
        b.shorts({0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, "VEC4");
    expectError(b.gltf(), "vertex 2 uses joint 2, beyond the skin's 2 joints");
}

TEST(GltfBadInput, NonTrianglePrimitivesAreSkippedAndAloneAreAnError) {
    GltfBuilder b = test::stripCharacter();
    nlohmann::json lines = test::stripPrimitive(b);
    lines["mode"] = 1;
    b.doc["meshes"][0]["primitives"].push_back(lines);
    std::vector<std::string> notes;
    const std::string text = b.gltf();
    const model::SkinnedModel m = test::loadText(text, &notes);
    EXPECT_EQ(m.triangleCount(), 4u);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_NE(notes[0].find("mesh 0 primitive 1 draws points or lines; skipped"), std::string::npos) << notes[0];
    test::stripPrimitive(b)["mode"] = 0;
    expectError(b.gltf(), "no triangles");
    test::stripPrimitive(b)["mode"] = 9;
    expectError(b.gltf(), "unknown mode 9");
}

TEST(GltfBadInput, MissingAttributes) {
    GltfBuilder b = test::stripCharacter();
    test::stripPrimitive(b)["attributes"].erase("JOINTS_0");
    expectError(b.gltf(), "WEIGHTS_0 without JOINTS_0");
    test::stripPrimitive(b)["attributes"].erase("WEIGHTS_0");
    expectError(b.gltf(), "no JOINTS_0/WEIGHTS_0");
    test::stripPrimitive(b)["attributes"].erase("POSITION");
    expectError(b.gltf(), "no POSITION");
}

TEST(GltfBadInput, BrokenAnimations) {
    GltfBuilder b = test::stripCharacter();
    auto& sampler = b.doc["animations"][0]["samplers"][0];
    sampler["input"] = b.floats({0.0f, 1.0f, 0.5f}, "SCALAR");
    expectError(b.gltf(), "animation 0 channel 0: key times decrease at key 2");
    sampler["input"] = b.floats({0.0f, 0.5f, 1.0f, 1.5f}, "SCALAR");
    expectError(b.gltf(), "3 values for 4 keys");
    sampler["interpolation"] = "CUBICSPLINE";
    expectError(b.gltf(), "CUBICSPLINE needs 3 per key");
    sampler["interpolation"] = "SMOOTH";
    expectError(b.gltf(), "unknown interpolation 'SMOOTH'");
    b = test::stripCharacter();
    b.doc["animations"][0]["channels"][0]["sampler"] = 5;
    expectError(b.gltf(), "sampler 5 does not exist");
    b = test::stripCharacter();
    b.doc["animations"][0]["channels"][0]["target"]["node"] = 42;
    expectError(b.gltf(), "target node 42 does not exist");
    b = test::stripCharacter();
    b.doc["animations"][0]["samplers"][0]["output"] = b.floats({0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1}, "VEC4");
    expectError(b.gltf(), "rotation key 0 is not a unit quaternion");
}

namespace {

// The strip with one more channel in its animation "bend": `path` of `node`, LINEAR over 0, 0.5, 1 s.
GltfBuilder stripWithChannel(int node, const std::string& path, const std::vector<float>& values) {
    GltfBuilder b = test::stripCharacter();
    const int input = b.floats({0.0f, 0.5f, 1.0f}, "SCALAR");
    const int output = b.floats(values, "VEC3");
    nlohmann::json& animation = b.doc["animations"][0];
    animation["samplers"].push_back({{"input", input}, {"output", output}});
    animation["channels"].push_back(
        {{"sampler", animation["samplers"].size() - 1}, {"target", {{"node", node}, {"path", path}}}});
    return b;
}

}  // namespace

TEST(GltfBadInput, FiniteKeysThatAnimateBeyondTheFiniteRangeAreRefusedNamingClipAndChannel) {
    // Each key is a finite float, so the loader's finiteness checks pass them; sampled, multiplied down
    // the hierarchy and by the vertices, they reach inf and NaN.
    const float big = 3e38f;
    expectError(stripWithChannel(2, "translation", {0, 1, 0, big, big, big, 0, 1, 0}).gltf(),
                "test.gltf: animation 0 'bend' channel 1 (translation of joint 'tip'): its keys can put vertices ");
    const std::string huge = stripWithChannel(1, "scale", {1, 1, 1, 1e20f, 1e20f, 1e20f, 1, 1, 1}).gltf();
    expectError(huge, "animation 0 'bend' channel 1 (scale of joint 'root'): its keys can put vertices ");
    expectError(huge, " from the origin, beyond the 1e+18 within which skinning stays finite");
    // Large but harmless: a joint scaled a thousandfold.
    EXPECT_NO_THROW(test::loadText(stripWithChannel(1, "scale", {1, 1, 1, 1e3f, 1e3f, 1e3f, 1, 1, 1}).gltf()));
}

TEST(GltfBadInput, RestPoseBeyondTheFiniteRangeIsRefused) {
    GltfBuilder b = test::stripCharacter();
    b.doc["nodes"][0]["scale"] = {1e19, 1e19, 1e19};  // "world", above the joints: the root transform
    expectError(b.gltf(), "test.gltf: the rest pose can put vertices ");
}

TEST(GltfBadInput, ExportPoseOfKeysNearTheFloatLimitFailsInsteadOfWritingInfinity) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("crowd-gltf-reach-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "huge.gltf") << stripWithChannel(1, "scale", {1, 1, 1, 3e38f, 3e38f, 3e38f, 1, 1, 1}).gltf();
    const test::ProgramResult r = test::runProgram(
        CROWD_RENDER_BINARY, "--model " + (dir / "huge.gltf").string() + " --clip bend --time 0.5 --export-pose " +
                                 (dir / "pose.obj").string());
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("animation 0 'bend' channel 1 (scale of joint 'root')"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "pose.obj"));
    std::filesystem::remove_all(dir);
}

TEST(GltfBadInput, DeeplyNestedJsonIsRefusedBeforeParsing) {
    // A million nested arrays in "extras" would overflow the stack of a recursive JSON reader.
    std::string text = test::stripCharacter().gltf();
    text.insert(1, "\"extras\": " + std::string(1000000, '[') + std::string(1000000, ']') + ", ");
    expectError(text, "JSON nested deeper than 64 levels");
}

TEST(GltfBadInput, UnsupportedRequiredExtension) {
    GltfBuilder b = test::stripCharacter();
    b.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    expectError(b.gltf(), "requires the extension KHR_draco_mesh_compression");
    b.doc["extensionsRequired"] = {"KHR_materials_unlit", "KHR_mesh_quantization"};
    EXPECT_NO_THROW(test::loadText(b.gltf()));
}

TEST(GltfBadInput, ImageInABufferViewPastItsBuffer) {
    // tinygltf 2.7 does not check an image's buffer view; the loader reads it only after checking.
    GltfBuilder b = test::stripCharacter();
    b.doc["images"] = {{{"bufferView", b.view(test::png2x2())}, {"mimeType", "image/png"}}};
    b.doc["bufferViews"].back()["byteOffset"] = 1u << 30;
    b.doc["textures"] = {{{"source", 0}}};
    b.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    expectError(b.gltf(), "runs past the end of buffer 0");
}

TEST(GltfBadInput, PngWithAnEmptyDataChunkDecodes) {
    // Fuzzer find (fuzz/regressions/png-empty-idat-chunk.glb): stb_image copied a zero-length IDAT
    // chunk to a null pointer. The loader drops such chunks before decoding.
    GltfBuilder b = test::stripCharacter();
    b.doc["images"] = {{{"bufferView", b.view(test::png2x2(true))}, {"mimeType", "image/png"}}};
    b.doc["textures"] = {{{"source", 0}}};
    b.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    const model::SkinnedModel m = test::loadText(b.gltf());
    EXPECT_EQ(m.baseColorTexture.rgba,
              (std::vector<std::uint8_t>{255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255}));
}

TEST(GltfBadInput, FuzzerFindsLoadOrFailCleanly) {
    // Every input the fuzzer ever crashed on is kept in fuzz/regressions (scripts/fuzz.sh replays them too).
    const std::filesystem::path dir = std::filesystem::path(CROWD_SOURCE_DIR) / "fuzz" / "regressions";
    if (!std::filesystem::is_directory(dir)) GTEST_SKIP() << dir << " missing";
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        std::ifstream file(entry.path(), std::ios::binary);
        const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
        loadsOrFailsCleanly(bytes);
        ++count;
    }
    EXPECT_GE(count, 1);
}

TEST(GltfBadInput, AssimpBrokenFilesLoadOrFailCleanly) {
    std::vector<std::filesystem::path> files;
    for (const char* root : {"/usr/share/assimp/models/glTF2", "/usr/share/assimp/models/glTF"}) {
        std::error_code error;
        if (!std::filesystem::is_directory(root, error)) continue;
        for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
            const std::filesystem::path& path = entry.path();
            if (entry.is_regular_file() && model::hasGltfExtension(path)) files.push_back(path);
        }
    }
    if (files.empty()) GTEST_SKIP() << "assimp-testmodels is not installed (scripts/setup.sh --tests)";
    int loaded = 0;
    for (const std::filesystem::path& path : files) {
        try {
            const model::SkinnedModel m = model::loadGltf(path);
            ++loaded;
            EXPECT_GT(m.triangleCount(), 0u) << path;
        } catch (const gpu::Error& error) {
            const std::string message = error.what();
            EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    }
    // simple_skin.gltf is the corpus's one skinned character.
    EXPECT_GE(loaded, 1) << "of " << files.size() << " files";
}

TEST(GltfBadInput, RecursiveNodesFromAssimpAreRejected) {
    const std::filesystem::path path = "/usr/share/assimp/models/glTF2/RecursiveNodes/RecursiveNodes.gltf";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "assimp-testmodels is not installed";
    EXPECT_THROW(model::loadGltf(path), gpu::Error);
}

TEST(GltfBadInput, CrowdRenderPrintsOneLineNamingTheFile) {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("crowd-gltf-cli-" + std::to_string(::getpid()) + ".gltf");
    GltfBuilder b = test::stripCharacter();
    b.doc["nodes"][2]["children"] = {2};
    std::ofstream(path) << b.gltf();
    for (const std::string flags :
         {"--list-clips", "--export-pose /tmp/never.obj", "--count 1 --frames 1 --out /tmp/never.png"}) {
        const test::ProgramResult r = test::runProgram(CROWD_RENDER_BINARY, "--model " + path.string() + " " + flags);
        EXPECT_EQ(r.exitCode, 1) << flags << "\n" << r.err;
        EXPECT_EQ(r.err, "crowd-render: " + path.string() + ": node 2 is its own child (the node graph has a cycle)\n")
            << flags;
    }
    std::filesystem::remove(path);
    const test::ProgramResult missing =
        test::runProgram(CROWD_RENDER_BINARY, "--model /nonexistent/dragon.glb --list-clips");
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_EQ(missing.err, "crowd-render: /nonexistent/dragon.glb: no such file\n");
}
