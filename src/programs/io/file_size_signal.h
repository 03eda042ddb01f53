#pragma once
// A file-size limit (`ulimit -f`, RLIMIT_FSIZE) is a failed write like a full disk, not a reason to die.

namespace io {

// Ignores SIGXFSZ, whose default action kills the process with no message (status 153) and leaves
// writeFile's temporary file behind. Ignored, a write past the limit fails with EFBIG, which
// writeFile reports in one line ("File too large") after removing its temporary file. Call once,
// first thing in main().
void failWritesPastTheFileSizeLimit();

}  // namespace io
