#pragma once
// Runs a program of the project and measures its peak resident memory (the kernel's high-water mark
// of the process), for tests that check memory stays flat over a long run.
#include <string>
#include <vector>

namespace test {

struct PeakMemoryResult {
    int exitCode = -1;
    long peakKilobytes = 0;  // ru_maxrss of the program (Linux: kilobytes)
};

// Starts `program` with `arguments` (no shell), stdout and stderr to /dev/null, and waits at most
// `timeoutSeconds` (then kills it: exit code 124).
PeakMemoryResult runMeasuringPeakMemory(const std::string& program, const std::vector<std::string>& arguments,
                                        int timeoutSeconds = 120);

}  // namespace test
