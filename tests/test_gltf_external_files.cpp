// A glTF file's external buffers and images come only from inside its folder (or --asset-root): a
// crafted file must not read, nor measure, files elsewhere on the machine.
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <gtest/gtest.h>

#include "gpu/vulkan_error.h"
#include "model/gltf_loader.h"
#include "support/gltf_builder.h"
#include "support/run_program.h"

namespace {

namespace fs = std::filesystem;

// <tmp>/crowd-gltf-files-<pid>/            secret.bin: the strip's own buffer, outside the model's folder
//                              model/      strip.bin, sub/strip.bin, and the .gltf files the tests write
class GltfExternalFiles : public ::testing::Test {
protected:
    void SetUp() override {
        top = fs::temp_directory_path() / ("crowd-gltf-files-" + std::to_string(::getpid()));
        fs::remove_all(top);
        fs::create_directories(top / "model" / "sub");
        strip = test::stripCharacter();
        // The secret is a valid buffer for the strip: a loader that followed the URI would load it and
        // export its bytes as vertex positions.
        for (const fs::path& file : {top / "secret.bin", top / "model" / "strip.bin", top / "model" / "sub" / "strip.bin"})
            std::ofstream(file, std::ios::binary)
                .write(reinterpret_cast<const char*>(strip.bin.data()), static_cast<std::streamsize>(strip.bin.size()));
    }
    void TearDown() override { fs::remove_all(top); }

    // Writes model/<name> with one buffer at `uri`; returns its path.
    fs::path modelWithBuffer(const std::string& uri, const std::string& name = "strip.gltf") {
        test::GltfBuilder b = strip;
        b.doc["buffers"] = {{{"byteLength", b.bin.size()}, {"uri", uri}}};
        const fs::path path = top / "model" / name;
        std::ofstream(path) << b.gltf(false);
        return path;
    }

    // The error loading `path` gives, or "" when it loads.
    static std::string loadError(const fs::path& path, const fs::path& assetRoot = {}) {
        try {
            model::loadGltf(path, nullptr, assetRoot);
        } catch (const gpu::Error& error) {
            return error.what();
        }
        return "";
    }

    fs::path top;
    test::GltfBuilder strip;
};

TEST_F(GltfExternalFiles, BuffersInsideTheModelsFolderLoad) {
    for (const std::string uri : {"strip.bin", "sub/strip.bin", "sub/../strip.bin", "./sub/strip.bin",
                                  "%73trip.bin" /* percent-encoded 's' */}) {
        EXPECT_EQ(loadError(modelWithBuffer(uri)), "") << uri;
    }
    // A symbolic link inside the folder to a file inside it is fine.
    fs::create_symlink(top / "model" / "sub" / "strip.bin", top / "model" / "link.bin");
    EXPECT_EQ(loadError(modelWithBuffer("link.bin")), "");
}

TEST_F(GltfExternalFiles, UrisLeadingOutsideTheFolderAreRefusedNamingTheUriAlone) {
    fs::create_symlink(top / "secret.bin", top / "model" / "innocent.bin");
    fs::create_directory_symlink(top, top / "model" / "up");
    const std::string absolute = (top / "secret.bin").string();
    const struct {
        std::string uri, shown, why;
    } cases[] = {
        {"../secret.bin", "../secret.bin", "leads outside the model's folder"},
        {"sub/../../secret.bin", "sub/../../secret.bin", "leads outside the model's folder"},
        {"%2e%2e/secret.bin", "../secret.bin", "leads outside the model's folder"},  // as tinygltf decodes it
        {"%2E%2E%2Fsecret.bin", "../secret.bin", "leads outside the model's folder"},
        {"innocent.bin", "innocent.bin", "leads outside the model's folder"},  // a link to the secret
        {"up/secret.bin", "up/secret.bin", "leads outside the model's folder"},  // a linked folder
        {absolute, absolute, "is an absolute path"},
        {"file://" + absolute, "file://" + absolute, "is not a relative path"},
        {"file:../secret.bin", "file:../secret.bin", "is not a relative path"},
    };
    for (const auto& c : cases) {
        const fs::path path = modelWithBuffer(c.uri);
        const std::string error = loadError(path);
        EXPECT_EQ(error.rfind(path.string() + ": URI '" + c.shown + "' " + c.why, 0), 0u) << c.uri << ": " << error;
        // Nothing about the file outside: neither its size nor its resolved path.
        EXPECT_EQ(error.find(std::to_string(strip.bin.size())), std::string::npos) << error;
        if (c.shown != absolute && c.shown.find("file:") != 0) {
            EXPECT_EQ(error.find(top.string() + "/secret.bin"), std::string::npos) << error;
        }
    }
}

TEST_F(GltfExternalFiles, ImagesOutsideTheFolderAreRefusedToo) {
    test::GltfBuilder b = strip;
    b.doc["images"] = {{{"uri", "../secret.png"}}};
    b.doc["textures"] = {{{"source", 0}}};
    b.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    const std::vector<std::uint8_t> png = test::png2x2();
    std::ofstream(top / "secret.png", std::ios::binary)
        .write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
    const fs::path path = top / "model" / "textured.gltf";
    std::ofstream(path) << b.gltf();
    EXPECT_EQ(loadError(path), path.string() + ": URI '../secret.png' leads outside the model's folder "
                                               "(a wider asset root, the assetRoot argument, allows it)");
}

TEST_F(GltfExternalFiles, TheWorkingDirectoryIsNotSearched) {
    // tinygltf tries "./<uri>" after the model's folder; a file that is only there is not found.
    const fs::path path = modelWithBuffer("only-in-cwd.bin");
    fs::copy_file(top / "secret.bin", top / "only-in-cwd.bin");
    const fs::path cwd = fs::current_path();
    fs::current_path(top);
    const std::string error = loadError(path);
    fs::current_path(cwd);
    EXPECT_NE(error.find("only-in-cwd.bin"), std::string::npos) << error;
    EXPECT_NE(error, "");
}

TEST_F(GltfExternalFiles, AnAssetRootWidensTheFolderButNotToAbsolutePaths) {
    EXPECT_EQ(loadError(modelWithBuffer("../secret.bin"), top), "");
    const fs::path absolute = modelWithBuffer((top / "secret.bin").string());
    EXPECT_NE(loadError(absolute, top).find("is an absolute path"), std::string::npos);
    // Still bounded: the root's own parent is outside it.
    const std::string error = loadError(modelWithBuffer("../secret.bin"), top / "model");
    EXPECT_NE(error.find("URI '../secret.bin' leads outside the asset root"), std::string::npos) << error;
    EXPECT_NE(loadError(modelWithBuffer("strip.bin"), top / "no-such-folder").find("is not a folder"),
              std::string::npos);
}

TEST_F(GltfExternalFiles, ProgramsRefuseByDefaultAndTakeAssetRoot) {
    const fs::path path = modelWithBuffer("../secret.bin");
    const std::string obj = (top / "pose.obj").string();
    const test::ProgramResult refused =
        test::runProgram(CROWD_RENDER_BINARY, "--model " + path.string() + " --export-pose " + obj);
    EXPECT_EQ(refused.exitCode, 1);
    EXPECT_EQ(refused.err, "crowd-render: " + path.string() +
                               ": URI '../secret.bin' leads outside the model's folder (--asset-root DIR allows a "
                               "wider one)\n");
    EXPECT_FALSE(fs::exists(obj));
    const test::ProgramResult allowed = test::runProgram(
        CROWD_RENDER_BINARY, "--model " + path.string() + " --asset-root " + top.string() + " --export-pose " + obj);
    EXPECT_EQ(allowed.exitCode, 0) << allowed.err;
    EXPECT_TRUE(fs::exists(obj));

    const std::string bench = "--models " + path.string() + " --counts 1 --frames 1 --warmup 0 --methods static "
                              "--size 32x32";
    EXPECT_EQ(test::runProgram(CROWD_BENCH_BINARY, bench).exitCode, 1);
    const test::ProgramResult benchAllowed =
        test::runProgram(CROWD_BENCH_BINARY, bench + " --asset-root " + top.string());
    EXPECT_EQ(benchAllowed.exitCode, 0) << benchAllowed.err;
}

}  // namespace
