#include "gpu_session.h"

#include <cstdio>

#include "exit_codes.h"

namespace lagoon::cli {

std::unique_ptr<vk::Context> open_context() {
  auto ctx = vk::Context::create(vk::ContextOptions::from_environment());
  if (!ctx) {
    std::fprintf(stderr, "lagoon: %s\n", ctx.error().message.c_str());
    return nullptr;
  }
  return std::move(ctx).value();
}

int validation_status(vk::Context& ctx) {
  const uint32_t failures = ctx.validation().failures();
  if (failures == 0) return kExitOk;
  std::fprintf(stderr, "lagoon: the Vulkan validation layer reported %u error(s); see the messages above\n",
               failures);
  return kExitValidation;
}

}  // namespace lagoon::cli
