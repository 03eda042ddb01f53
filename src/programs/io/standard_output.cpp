#include "io/standard_output.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <unistd.h>

namespace io {
namespace {

const char* programName = "";
bool reported = false;

void checkAtExit() {
    errno = 0;
    const bool flushed = std::fflush(stdout) == 0;
    const int error = errno;
    if (flushed && !std::ferror(stdout)) return;
    if (reported) ::_exit(1);  // one failure, one line: it was said already
    std::fprintf(stderr, "%s: cannot write standard output: %s\n", programName,
                 error != 0 ? std::strerror(error) : "write error");
    // _exit: this runs inside exit(), which must not be called again.
    ::_exit(1);
}

}  // namespace

void standardOutputFailureReported() { reported = true; }

void failOnUnwrittenStandardOutput(const char* program) {
    programName = program;
    std::atexit(checkAtExit);
}

}  // namespace io
