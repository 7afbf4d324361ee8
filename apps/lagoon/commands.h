// The `lagoon` subcommands. Each returns the process exit code (see kExit*).
#pragma once
#include <span>
#include <string>

#include "args.h"

namespace lagoon::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;     // missing/unreadable/invalid file, no device, Vulkan error
inline constexpr int kExitUsage = 2;       // bad command line
inline constexpr int kExitValidation = 3;  // LAGOON_VALIDATION=1 and the validation layer reported errors

struct Command {
  CommandSpec spec;
  int (*run)(const ParsedArgs& args);
};

const Command& info_command();
const Command& render_command();
const Command& bench_command();
const Command& export_command();
const Command& probe_command();
const Command& lut_command();

}  // namespace lagoon::cli
