#include "io/output_file.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "gpu/vulkan_error.h"

namespace io {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, int error) {
    throw gpu::Error("cannot write " + path.string() + ": " + std::strerror(error));
}

// Devices, FIFOs and the process's own streams (/dev/stdout, /proc/self/fd/N) are written in place:
// renaming over them would replace a device node, or a file a shell opened for us, with a new file.
bool writtenInPlace(const std::filesystem::path& path) {
    const std::string text = path.string();
    if (text.rfind("/dev/", 0) == 0 || text.rfind("/proc/", 0) == 0) return true;
    struct stat info {};
    return ::stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode);
}

// The regular file to replace: a symbolic link's target, so that the link stays a link.
std::filesystem::path replacedFile(const std::filesystem::path& path) {
    std::error_code error;
    if (!std::filesystem::is_symlink(path, error)) return path;
    std::filesystem::path target = std::filesystem::canonical(path, error);
    return error ? path : target;
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
    if (path.empty()) throw gpu::Error("cannot write a file with an empty name");
    if (writtenInPlace(path))
        writeInPlace(path, bytes);
    else
        writeReplacing(path, bytes);
}

void writeFile(const std::filesystem::path& path, std::string_view text) {
    writeFile(path, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

void checkWritable(const std::filesystem::path& path) {
    if (path.empty()) throw gpu::Error("cannot write a file with an empty name");
    if (writtenInPlace(path)) {
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
