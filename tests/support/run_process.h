// Runs a command line through the shell and captures its exit code and combined output (CLI tests).
#pragma once
#include <filesystem>
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

// The built `lagoon` command with `args` (already quoted where needed), with `env` as in run_process.
ProcessResult lagoon(const std::string& args, const std::string& env = "");

// The shipped default scene, the one most CLI tests start from.
inline const std::string kDefaultScene = std::string(LAGOON_SOURCE_DIR) + "/scenes/default.json";

// A whole file's bytes ("" when it cannot be read: the comparison that uses it fails).
std::string read_file(const std::filesystem::path& path);

}  // namespace lagoon::test
