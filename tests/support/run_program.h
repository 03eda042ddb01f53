#pragma once
// Runs a program of the project as a user would, capturing exit code, stdout and stderr.
#include <string>

namespace test {

struct ProgramResult {
    int exitCode = -1;
    std::string out;
    std::string err;
};

// `arguments` is appended to the program path as-is (shell syntax); `environment` is prefixed
// (e.g. "VK_ICD_FILENAMES=/nonexistent"). A time limit guards against hangs.
ProgramResult runProgram(const std::string& program, const std::string& arguments,
                         const std::string& environment = "", int timeoutSeconds = 120);

// `program` as a command whose files may grow to at most `blocks` x 512 bytes (RLIMIT_FSIZE), as a plain
// `ulimit -f` sets it: SIGXFSZ is not ignored for the program, so a write past the limit kills it
// unless it ignores the signal itself. Pass it to runProgram.
std::string withFileSizeLimit(const std::string& program, int blocks);

}  // namespace test
