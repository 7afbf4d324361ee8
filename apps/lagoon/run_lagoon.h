// The `lagoon` command as a function: the executable's main() and the Python module's lagoon.run() (and
// lagoon.export, lagoon.render_sequence) run the same commands through it, so the two cannot drift apart.
#pragma once
#include <span>
#include <string>

namespace lagoon::cli {

// `args` as after the program name ("render", "--scene", ...): parses them, runs the command and returns
// its exit code (kExit*); usage errors, Vulkan errors and exceptions are printed to stderr as the
// executable prints them.
int run_lagoon(std::span<const std::string> args);

}  // namespace lagoon::cli
