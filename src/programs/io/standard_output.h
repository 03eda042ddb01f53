#pragma once
// Standard output is an output too: what the programs print there (summaries, clip lists, help) must
// not be lost without a word when it is redirected to a full disk or /dev/full.

namespace io {

// At exit, flushes standard output; if that or any earlier write to it failed, prints one line
// "<program>: cannot write standard output: <reason>" on stderr and ends the process with status 1.
// Call once, first thing in main().
void failOnUnwrittenStandardOutput(const char* program);
// A failed write to standard output that the program has already reported in its own line (an output
// file that names standard output, io::writeFile): the exit check then ends with status 1 without a
// second line about the same stream.
void standardOutputFailureReported();

}  // namespace io
