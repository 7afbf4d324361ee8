#include "support/vk_fixture.h"

#include <cstdlib>
#include <memory>
#include <string>

namespace lagoon::test {

vk::Context& gpu() {
  static std::unique_ptr<vk::Context> ctx = [] {
    vk::ContextOptions options = vk::ContextOptions::from_environment();
    options.validation = true;
    auto created = vk::Context::create(options);
    if (!created) {
      std::fprintf(stderr, "cannot create the test's Vulkan context: %s\n", created.error().message.c_str());
      std::abort();  // every GPU test needs it; failing loudly beats a cascade of skips
    }
    return std::move(created).value();
  }();
  return *ctx;
}

void GpuTest::SetUp() {
  failures_before_ = gpu().validation().failures();
}

void GpuTest::TearDown() {
  const uint32_t failures = gpu().validation().failures() - failures_before_;
  if (failures == 0) return;
  std::string messages;
  for (const auto& m : gpu().validation().messages()) messages += "\n  " + m;
  ADD_FAILURE() << "the Vulkan validation layer reported " << failures << " problem(s):" << messages;
}

}  // namespace lagoon::test
