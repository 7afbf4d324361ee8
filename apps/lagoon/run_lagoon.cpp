// The `lagoon` command's dispatch: the commands' table, the overview and the error handling around a run.
#include "run_lagoon.h"

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "commands.h"
#include "vk/check.h"
#include "vulkan_advice.h"

namespace lagoon::cli {
namespace {

const std::vector<const Command*>& commands() {
  static const std::vector<const Command*> list{
      &info_command(), &render_command(), &export_command(),         &probe_command(),
      &lut_command(),  &bench_command(),  &compare_images_command(), &compare_command(),
      &soak_command(), &sky_command(),    &dataset_command(),        &validate_command(),
  };
  return list;
}

void print_overview(FILE* out) {
  std::fprintf(out, "usage: lagoon <command> [options]\n\ncommands:\n");
  for (const Command* c : commands())
    std::fprintf(out, "  %-14s %s\n", c->spec.name.c_str(), c->spec.summary.c_str());
  std::fprintf(out, "\n'lagoon <command> --help' describes a command's options.\n");
}

}  // namespace

int run_lagoon(std::span<const std::string> argv) {
  if (argv.empty()) {
    print_overview(stderr);
    return kExitUsage;
  }
  const std::string& name = argv[0];
  if (name == "--help" || name == "-h" || name == "help") {
    print_overview(stdout);
    return kExitOk;
  }
  const Command* command = nullptr;
  for (const Command* c : commands())
    if (c->spec.name == name) command = c;
  if (!command) {
    std::fprintf(stderr, "lagoon: unknown command '%s'\n\n", name.c_str());
    print_overview(stderr);
    return kExitUsage;
  }
  auto args = parse_args(command->spec, argv.subspan(1));
  if (!args) {
    std::fprintf(stderr, "lagoon %s: %s\n\n%s", name.c_str(), args.error().message.c_str(),
                 usage(command->spec).c_str());
    return kExitUsage;
  }
  if (args->help) {
    std::printf("%s", usage(command->spec).c_str());
    return kExitOk;
  }
  try {
    return command->run(*args);
  } catch (const vk::VulkanError& e) {
    std::fprintf(stderr, "lagoon %s: Vulkan error: %s\n", name.c_str(), explain_vulkan_error(e).c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lagoon %s: %s\n", name.c_str(), e.what());
  }
  return kExitFailure;
}

}  // namespace lagoon::cli
