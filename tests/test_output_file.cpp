// io::writeFile, which every output of the programs goes through: the whole file or none, failures
// named, an existing file replaced only by a complete one.
#include <filesystem>
#include <fstream>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

#include <gtest/gtest.h>

#include "app/error.h"
#include "io/output_file.h"

namespace {

class OutputFile : public ::testing::Test {
protected:
    void SetUp() override {
        dir = std::filesystem::temp_directory_path() / ("crowd-output-file-" + std::to_string(::getpid()));
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
    }
    void TearDown() override { std::filesystem::remove_all(dir); }

    std::string read(const std::filesystem::path& path) const {
        std::ifstream file(path, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
    }
    std::vector<std::string> filesInDir() const {
        std::vector<std::string> names;
        for (const auto& entry : std::filesystem::directory_iterator(dir)) names.push_back(entry.path().filename());
        std::sort(names.begin(), names.end());
        return names;
    }
    // The message of the app::Error `write` throws, or "" when it throws none.
    template <typename Write>
    std::string errorOf(Write write) const {
        try {
            write();
        } catch (const app::Error& error) {
            return error.what();
        }
        return "";
    }

    std::filesystem::path dir;
};

TEST_F(OutputFile, WritesExactlyTheBytesAndNothingElse) {
    const std::string bytes("binary\0data\n", 12);
    io::writeFile(dir / "out.bin", bytes);
    EXPECT_EQ(read(dir / "out.bin"), bytes);
    EXPECT_EQ(filesInDir(), std::vector<std::string>{"out.bin"});
}

TEST_F(OutputFile, ReplacesAnExistingFileWhole) {
    std::ofstream(dir / "out.txt") << "a much longer previous content that must not survive";
    io::writeFile(dir / "out.txt", std::string_view("new"));
    EXPECT_EQ(read(dir / "out.txt"), "new");
    EXPECT_EQ(filesInDir(), std::vector<std::string>{"out.txt"});
}

TEST_F(OutputFile, AReplacedFileKeepsItsPermissions) {
    std::ofstream(dir / "private.json") << "{}";
    std::filesystem::permissions(dir / "private.json", std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
    io::writeFile(dir / "private.json", std::string_view("{\"a\": 1}"));
    EXPECT_EQ(std::filesystem::status(dir / "private.json").permissions(),
              std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
}

TEST_F(OutputFile, TheLongestFileNameAFolderAllowsCanBeWritten) {
    const std::string name(255, 'x');  // NAME_MAX; the temporary file beside it must still fit
    io::checkWritable(dir / name);
    io::writeFile(dir / name, std::string_view("ok"));
    EXPECT_EQ(read(dir / name), "ok");
}

TEST_F(OutputFile, ReplacesTheFileASymbolicLinkNamesAndKeepsTheLink) {
    std::ofstream(dir / "target.txt") << "old";
    std::filesystem::create_symlink("target.txt", dir / "link.txt");
    io::writeFile(dir / "link.txt", std::string_view("new"));
    EXPECT_TRUE(std::filesystem::is_symlink(dir / "link.txt"));
    EXPECT_EQ(read(dir / "target.txt"), "new");
}

TEST_F(OutputFile, ADanglingLinkIsWrittenThroughToTheFileItNames) {
    // As the shell's `>` does: the link's target is created and the link stays a link.
    std::filesystem::create_directories(dir / "results");
    std::filesystem::create_symlink("results/out.png", dir / "link.png");
    io::checkWritable(dir / "link.png");
    io::writeFile(dir / "link.png", std::string_view("new"));
    EXPECT_TRUE(std::filesystem::is_symlink(dir / "link.png"));
    EXPECT_EQ(read(dir / "results" / "out.png"), "new");
    EXPECT_EQ(filesInDir(), (std::vector<std::string>{"link.png", "results"}));
}

TEST_F(OutputFile, ADanglingLinkIntoAMissingFolderIsAnErrorNamingTheLink) {
    std::filesystem::create_symlink("no-such-folder/out.png", dir / "link.png");
    const std::filesystem::path link = dir / "link.png";
    EXPECT_EQ(errorOf([&] { io::writeFile(link, std::string_view("x")); }),
              "cannot write " + link.string() + ": No such file or directory");
    EXPECT_TRUE(std::filesystem::is_symlink(link));
}

TEST_F(OutputFile, ALoopOfLinksIsAnErrorNamingThePath) {
    std::filesystem::create_symlink("b", dir / "a");
    std::filesystem::create_symlink("a", dir / "b");
    EXPECT_EQ(errorOf([&] { io::writeFile(dir / "a", std::string_view("x")); }),
              "cannot write " + (dir / "a").string() + ": Too many levels of symbolic links");
    EXPECT_EQ(filesInDir(), (std::vector<std::string>{"a", "b"}));
}

TEST_F(OutputFile, AFileUnderDevIsJudgedByWhatItIsNotByItsName) {
    // /dev/shm holds regular files: a new one is created, an existing one replaced whole (a new inode),
    // as anywhere else; only devices and FIFOs are written in place.
    const std::filesystem::path shm = "/dev/shm";
    if (::access(shm.c_str(), W_OK) != 0) GTEST_SKIP() << "no writable /dev/shm";
    const std::filesystem::path file = shm / ("crowd-output-file-" + std::to_string(::getpid()) + ".txt");
    io::checkWritable(file);
    io::writeFile(file, std::string_view("first"));
    EXPECT_EQ(read(file), "first");
    struct stat before {}, after {};
    ASSERT_EQ(::stat(file.c_str(), &before), 0);
    io::writeFile(file, std::string_view("second"));
    ASSERT_EQ(::stat(file.c_str(), &after), 0);
    EXPECT_EQ(read(file), "second");
    EXPECT_NE(before.st_ino, after.st_ino) << "rewritten in place instead of replaced";
    std::filesystem::remove(file);
}

TEST_F(OutputFile, AFifoIsWrittenInPlace) {
    const std::filesystem::path fifo = dir / "pipe";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    io::checkWritable(fifo);  // returns without waiting for a reader
    std::string received;
    std::thread reader([&] { received = read(fifo); });
    io::writeFile(fifo, std::string_view("through the pipe"));
    reader.join();
    EXPECT_EQ(received, "through the pipe");
    EXPECT_EQ(filesInDir(), std::vector<std::string>{"pipe"});
}

TEST_F(OutputFile, AFullDeviceIsAnErrorNamingIt) {
    const std::string message = errorOf([] { io::writeFile("/dev/full", std::string_view("x")); });
    EXPECT_EQ(message, "cannot write /dev/full: No space left on device");
    EXPECT_NO_THROW(io::writeFile("/dev/null", std::string_view("x")));  // devices are written in place
}

TEST_F(OutputFile, AMissingFolderIsAnErrorNamingThePathAndCreatesNothing) {
    const std::filesystem::path path = dir / "no-such-folder" / "out.png";
    EXPECT_EQ(errorOf([&] { io::writeFile(path, std::string_view("x")); }),
              "cannot write " + path.string() + ": No such file or directory");
    EXPECT_EQ(errorOf([&] { io::checkWritable(path); }), "cannot write " + path.string() + ": No such file or directory");
    EXPECT_TRUE(filesInDir().empty());
}

TEST_F(OutputFile, CheckWritableLeavesTheFolderAsItWas) {
    io::checkWritable(dir / "new.png");
    EXPECT_TRUE(filesInDir().empty());
    std::ofstream(dir / "old.png") << "kept";
    io::checkWritable(dir / "old.png");
    EXPECT_EQ(read(dir / "old.png"), "kept");
    EXPECT_EQ(filesInDir(), std::vector<std::string>{"old.png"});
}

}  // namespace
