#pragma once
// Every file the programs write (images, JSON, CSV, OBJ, screenshots) goes through here, so that a
// write that fails says so, and a run that fails leaves nothing under the requested name that could
// pass for a complete result.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace io {

// Writes `bytes` as the whole content of `path`, deciding by what the path names (after symbolic
// links), not by its spelling:
//  - a regular file, or nothing yet: written under a temporary name in the same folder, flushed to
//    disk, closed and only then renamed over it, every step checked; on failure the temporary file is
//    removed and an existing file is left as it was. A symbolic link is followed to its target, which
//    is created if it does not exist yet (a dangling link), and the link stays a link;
//  - the file open as standard output or error (/dev/stdout, /proc/self/fd/1, or that file's own
//    name): appended to that stream after what stdio holds for it, never reopened or truncated;
//  - anything else that exists (/dev/null, /dev/full, a FIFO): written in place, every write and the
//    close checked.
// Throws app::Error "cannot write <path>: <reason>".
void writeFile(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);
void writeFile(const std::filesystem::path& path, std::string_view text);

// Checks, before a long run, that writeFile(path) can create its temporary file (the folder exists and
// is writable) or open `path` in place. Creates and removes nothing else. Throws like writeFile.
void checkWritable(const std::filesystem::path& path);

}  // namespace io
