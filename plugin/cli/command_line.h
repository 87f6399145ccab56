#pragma once
// The `probeproxy` command line as a function: parses argv, runs the verb, prints its report on
// stdout and one line per error on stderr, and returns the exit code. main() is only this; the
// command-line fuzz target (tests/fuzz/fuzz_command_line.cpp) calls it with argument lists of
// its own.

namespace probeproxy::cli {

// 0 done, 1 findings (validate), kExitBadInput (2) bad input or not available,
// kExitInternalError (3) a bug: an exception that is not the input's fault.
inline constexpr int kExitInternalError = 3;

int runCommandLine(int argc, char** argv);

}  // namespace probeproxy::cli
