// lagoon: the command-line front of the Lagoon ocean simulator and renderer.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "commands.h"
#include "vk/check.h"
#include "vulkan_advice.h"

namespace {

using lagoon::cli::Command;

const std::vector<const Command*>& commands() {
  static const std::vector<const Command*> list{
      &lagoon::cli::info_command(),
      &lagoon::cli::render_command(),
      &lagoon::cli::export_command(),
      &lagoon::cli::probe_command(),
      &lagoon::cli::lut_command(),
      &lagoon::cli::bench_command(),
      &lagoon::cli::compare_images_command(),
      &lagoon::cli::compare_command(),
      &lagoon::cli::soak_command(),
      &lagoon::cli::sky_command(),
      &lagoon::cli::dataset_command(),
      &lagoon::cli::validate_command(),
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

int main(int argc, char** argv) {
  using namespace lagoon::cli;
  if (argc < 2) {
    print_overview(stderr);
    return kExitUsage;
  }
  const std::string name = argv[1];
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
  const std::vector<std::string> rest(argv + 2, argv + argc);
  auto args = parse_args(command->spec, rest);
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
  } catch (const lagoon::vk::VulkanError& e) {
    std::fprintf(stderr, "lagoon %s: Vulkan error: %s\n", name.c_str(),
                 lagoon::cli::explain_vulkan_error(e).c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lagoon %s: %s\n", name.c_str(), e.what());
  }
  return kExitFailure;
}
