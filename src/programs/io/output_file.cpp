#include "io/output_file.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "app/error.h"
#include "io/standard_output.h"

namespace io {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, int error) {
    throw app::Error("cannot write " + path.string() + ": " + std::strerror(error));
}

// What writing a path means is decided by what the path names, never by how it is spelled (a new
// /dev/shm/x.png is a regular file like any other).
enum class Target {
    StandardStream,  // the file open as our standard output or error (/dev/stdout, or its own name)
    InPlace,         // an existing device, FIFO or other non-regular file (/dev/null, /dev/full)
    Replaced,        // a regular file, or none yet: written whole under a temporary name, then renamed
};

// The standard stream (1 or 2) that `info` is the open file of, or -1. Reopening it (O_TRUNC at
// offset 0) would write over what the program printed there, or be written over by it.
int standardStreamOf(const struct stat& info) {
    for (const int fd : {STDOUT_FILENO, STDERR_FILENO}) {
        struct stat stream {};
        if (::fstat(fd, &stream) == 0 && stream.st_dev == info.st_dev && stream.st_ino == info.st_ino) return fd;
    }
    return -1;
}

Target targetOf(const std::filesystem::path& path, int& streamFd) {
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0) return Target::Replaced;  // nothing there yet (or a dangling link)
    streamFd = standardStreamOf(info);
    if (streamFd >= 0) return Target::StandardStream;
    return S_ISREG(info.st_mode) ? Target::Replaced : Target::InPlace;
}

// The name a path stands for once its symbolic links are followed, the last one included even when
// it points at nothing yet: like the shell's `>`, writing through a dangling link creates its target,
// and the link stays a link. Fails with ELOOP as open(2) would on a cycle.
std::filesystem::path replacedFile(const std::filesystem::path& path) {
    constexpr int kMaxLinks = 40;  // Linux's own limit on links followed in one lookup
    std::filesystem::path file = path;
    for (int link = 0; link < kMaxLinks; ++link) {
        struct stat info {};
        if (::lstat(file.c_str(), &info) != 0 || !S_ISLNK(info.st_mode)) return file;
        std::error_code error;
        const std::filesystem::path target = std::filesystem::read_symlink(file, error);
        if (error) fail(path, error.value());
        file = target.is_absolute() ? target : file.parent_path() / target;
    }
    fail(path, ELOOP);
}

// A name beside `file` that nothing else uses: hidden, and unique per process and call. The target's
// name is cut so that a name of the longest length a folder allows still gets a temporary file.
std::filesystem::path temporaryName(const std::filesystem::path& file) {
    static std::atomic<unsigned> counter{0};
    std::string name = ".";
    name += file.filename().string().substr(0, 200);
    name += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    return file.parent_path() / name;
}

// Opens a new temporary file beside `file`: mode 0666 less the umask like any new file, or the mode of
// the file it will replace (a private file stays private).
int createTemporary(const std::filesystem::path& file, std::filesystem::path& temporary) {
    struct stat existing {};
    const bool replaces = ::stat(file.c_str(), &existing) == 0 && S_ISREG(existing.st_mode);
    for (int attempt = 0;; ++attempt) {
        temporary = temporaryName(file);
        const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0 && replaces && ::fchmod(fd, existing.st_mode & 07777) != 0) {
            const int error = errno;
            ::close(fd);
            ::unlink(temporary.c_str());
            errno = error;
            return -1;
        }
        if (fd >= 0 || errno != EEXIST || attempt == 100) return fd;
    }
}

// write(2) until every byte is out; returns 0 or the errno of the failure.
int writeAll(int fd, std::span<const std::uint8_t> bytes) {
    while (!bytes.empty()) {
        const ssize_t written = ::write(fd, bytes.data(), bytes.size());
        if (written < 0 && errno == EINTR) continue;
        if (written < 0) return errno;
        if (written == 0) return EIO;
        bytes = bytes.subspan(static_cast<std::size_t>(written));
    }
    return 0;
}

// Appends to the standard stream after what stdio still holds for it, so that both arrive whole and
// in the order the program produced them.
void writeToStream(const std::filesystem::path& path, int fd, std::span<const std::uint8_t> bytes) {
    std::fflush(fd == STDOUT_FILENO ? stdout : stderr);
    const int error = writeAll(fd, bytes);
    if (error == 0) return;
    // The line that names this file reports the stream's failure; the exit check says nothing more.
    if (fd == STDOUT_FILENO) standardOutputFailureReported();
    fail(path, error);
}

void writeInPlace(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) fail(path, errno);
    int error = writeAll(fd, bytes);
    // Close reports what a device or network file system only found out after the writes.
    if (::close(fd) != 0 && error == 0 && errno != EINTR) error = errno;
    if (error != 0) fail(path, error);
}

void writeReplacing(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
    const std::filesystem::path file = replacedFile(path);
    std::filesystem::path temporary;
    const int fd = createTemporary(file, temporary);
    if (fd < 0) fail(path, errno);
    int error = writeAll(fd, bytes);
    // fsync: a full disk or a quota may only show when the data goes out; rename must not publish a
    // file whose bytes are not all there.
    if (error == 0 && ::fsync(fd) != 0 && errno != EINVAL) error = errno;
    if (::close(fd) != 0 && error == 0 && errno != EINTR) error = errno;
    if (error == 0 && ::rename(temporary.c_str(), file.c_str()) != 0) error = errno;
    if (error != 0) {
        ::unlink(temporary.c_str());
        fail(path, error);
    }
}

}  // namespace

void writeFile(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
    if (path.empty()) throw app::Error("cannot write a file with an empty name");
    int streamFd = -1;
    switch (targetOf(path, streamFd)) {
        case Target::StandardStream: return writeToStream(path, streamFd, bytes);
        case Target::InPlace: return writeInPlace(path, bytes);
        case Target::Replaced: return writeReplacing(path, bytes);
    }
}

void writeFile(const std::filesystem::path& path, std::string_view text) {
    writeFile(path, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

void checkWritable(const std::filesystem::path& path) {
    if (path.empty()) throw app::Error("cannot write a file with an empty name");
    int streamFd = -1;
    const Target target = targetOf(path, streamFd);
    if (target == Target::StandardStream) {
        const int flags = ::fcntl(streamFd, F_GETFL);
        if (flags < 0 || (flags & O_ACCMODE) == O_RDONLY) fail(path, EBADF);
        return;
    }
    if (target == Target::InPlace) {
        struct stat info {};
        if (::stat(path.c_str(), &info) == 0 && S_ISFIFO(info.st_mode)) return;  // opening would wait for a reader
        const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
        if (fd < 0) fail(path, errno);
        ::close(fd);
        return;
    }
    std::filesystem::path temporary;
    const int fd = createTemporary(replacedFile(path), temporary);
    if (fd < 0) fail(path, errno);
    ::close(fd);
    ::unlink(temporary.c_str());
}

}  // namespace io
