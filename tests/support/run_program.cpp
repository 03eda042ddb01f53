#include "support/run_program.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace test {
namespace {

std::string slurp(const std::filesystem::path& path) {
    std::ifstream file(path);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

}  // namespace

ProgramResult runProgram(const std::string& program, const std::string& arguments, const std::string& environment,
                         int timeoutSeconds) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("crowd-run-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string command = "env " + environment + " timeout " + std::to_string(timeoutSeconds) + " " + program +
                                " " + arguments + " >" + (dir / "out").string() + " 2>" + (dir / "err").string() +
                                " </dev/null";
    const int status = std::system(command.c_str());
    ProgramResult result;
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    result.out = slurp(dir / "out");
    result.err = slurp(dir / "err");
    std::filesystem::remove_all(dir);
    return result;
}

std::string withFileSizeLimit(const std::string& program, int blocks) {
    // POSIX sh's ulimit -f counts 512-byte blocks; "$0" "$@" pass the program and runProgram's arguments on.
    // SIGXFSZ keeps its default action (death), as under a user's shell: the program must handle it.
    return "sh -c 'ulimit -f " + std::to_string(blocks) + "; exec \"$0\" \"$@\"' " + program;
}

}  // namespace test
