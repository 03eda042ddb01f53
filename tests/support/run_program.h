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

}  // namespace test
