// probeproxy: the command-line front end. Reports go to stdout (JSON under --json), progress
// and errors to stderr. Exit codes: 0 done, 1 findings (validate), 2 bad input or not available,
// 3 an internal error.

#include "plugin/cli/command_line.h"

int main(int argc, char** argv) { return probeproxy::cli::runCommandLine(argc, argv); }
