// GPU tests share one Vulkan context per test process, always with the validation layer on. Each test
// derived from GpuTest fails when the layer reported anything during that test.
#pragma once
#include <gtest/gtest.h>

#include "vk/context.h"

namespace lagoon::test {

// The process's context (created on first use, from the environment, validation forced on).
vk::Context& gpu();

class GpuTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;
  vk::Context& ctx() { return gpu(); }

 private:
  uint32_t failures_before_ = 0;
};

}  // namespace lagoon::test
