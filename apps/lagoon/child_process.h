// Running another program (an older `lagoon` for `bench render --baseline`) and waiting for it, its output
// going to a log file rather than into this command's own.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "core/result.h"

namespace lagoon::cli {

// Runs `argv` (argv[0] is the program's path, not searched in PATH) with stdout and stderr written to `log`;
// returns its exit status, or why it could not start or was killed.
Result<int> run_child(const std::vector<std::string>& argv, const std::filesystem::path& log);

}  // namespace lagoon::cli
