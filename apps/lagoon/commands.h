// The `lagoon` subcommands. Each returns the process exit code (see kExit*).
#pragma once
#include <span>
#include <string>

#include "args.h"
#include "exit_codes.h"

namespace lagoon::cli {

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
const Command& compare_images_command();
const Command& compare_command();
const Command& soak_command();
const Command& sky_command();
const Command& dataset_command();
const Command& validate_command();

}  // namespace lagoon::cli
