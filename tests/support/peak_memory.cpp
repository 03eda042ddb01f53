#include "support/peak_memory.h"

#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace test {
namespace {

[[noreturn]] void execInChild(const std::string& program, const std::vector<std::string>& arguments) {
    const int devNull = ::open("/dev/null", O_RDWR);
    ::dup2(devNull, STDIN_FILENO);
    ::dup2(devNull, STDOUT_FILENO);
    ::dup2(devNull, STDERR_FILENO);
    std::vector<char*> argv{const_cast<char*>(program.c_str())};
    for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(program.c_str(), argv.data());
    ::_exit(127);
}

}  // namespace

PeakMemoryResult runMeasuringPeakMemory(const std::string& program, const std::vector<std::string>& arguments,
                                        int timeoutSeconds) {
    const pid_t pid = ::fork();
    if (pid == 0) execInChild(program, arguments);
    PeakMemoryResult result;
    if (pid < 0) return result;
    // wait4 gives this child's own rusage (not that of every child the test process ever had).
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutSeconds);
    int status = 0;
    rusage usage{};
    while (::wait4(pid, &status, WNOHANG, &usage) == 0) {
        if (std::chrono::steady_clock::now() > deadline) {
            ::kill(pid, SIGKILL);
            ::wait4(pid, &status, 0, &usage);
            result.exitCode = 124;
            result.peakKilobytes = usage.ru_maxrss;
            return result;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    result.peakKilobytes = usage.ru_maxrss;
    return result;
}

}  // namespace test
