// GPU tests share one Vulkan context per test process, always with the validation layer on. Each test
// derived from GpuTest fails when the layer reported anything during that test.
#pragma once
#include <gtest/gtest.h>

#include <cstddef>
#include <cstring>
#include <vector>

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

// Read-back bytes as values of T (whole values only).
template <typename T>
std::vector<T> from_bytes(const std::vector<std::byte>& bytes) {
  std::vector<T> out(bytes.size() / sizeof(T));
  std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
  return out;
}

}  // namespace lagoon::test
