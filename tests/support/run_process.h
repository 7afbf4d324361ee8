// Runs a command line through the shell and captures its exit code and combined output (CLI tests).
#pragma once
#include <string>

namespace lagoon::test {

struct ProcessResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr interleaved
};

// `env` is prepended as shell assignments, e.g. "LAGOON_DEVICE=nope".
ProcessResult run_process(const std::string& command_line, const std::string& env = "");

// Quotes one argument for the shell.
std::string shell_quote(const std::string& arg);

}  // namespace lagoon::test
