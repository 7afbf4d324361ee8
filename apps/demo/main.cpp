// lagoon-demo: the ocean in a window with a live parameter panel (docs/demo.md).
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "demo_app.h"
#include "demo_options.h"
#include "exit_codes.h"
#include "vulkan_advice.h"

int main(int argc, char** argv) {
  try {
    const std::vector<std::string> args(argv + 1, argv + argc);
    int exit_code = lagoon::cli::kExitOk;
    auto options = lagoon::demo::parse_demo_options(args, exit_code);
    if (!options) return exit_code;
    return lagoon::demo::run_demo(std::move(*options));
  } catch (const lagoon::vk::VulkanError& e) {
    std::fprintf(stderr, "lagoon-demo: Vulkan error: %s\n", lagoon::cli::explain_vulkan_error(e).c_str());
    return lagoon::cli::kExitFailure;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lagoon-demo: %s\n", e.what());
    return lagoon::cli::kExitFailure;
  }
}
