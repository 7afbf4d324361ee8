// Frames in flight: objects deferred during a frame live until that frame's fence has been waited on.
#include "vk/frame_ring.h"

#include <gtest/gtest.h>

#include "lagoon_test_shaders/shaders.h"
#include "support/vk_fixture.h"
#include "vk/barriers.h"
#include "vk/pipeline.h"

namespace lagoon::test {
namespace {

class FrameRingTest : public GpuTest {};

struct Probe {
  bool* destroyed = nullptr;
  explicit Probe(bool* flag) : destroyed(flag) {}
  Probe(Probe&& other) noexcept : destroyed(std::exchange(other.destroyed, nullptr)) {}
  ~Probe() {
    if (destroyed) *destroyed = true;
  }
};

TEST_F(FrameRingTest, DeferredObjectsOutliveTheirFrame) {
  vk::FrameRing ring(ctx(), 2);
  const vk::ComputePipeline saxpy = vk::ComputePipeline::create(ctx(), shaders::gpu_saxpy_comp);
  vk::Buffer x =
      vk::Buffer::create(ctx(), 1024 * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUsage::Upload);
  vk::Buffer y =
      vk::Buffer::create(ctx(), 1024 * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUsage::Readback);
  for (float& v : x.mapped_as<float>()) v = 1.0f;
  for (float& v : y.mapped_as<float>()) v = 0.0f;
  struct Push {
    float a;
    uint32_t n;
  } push{1.0f, 1024};

  bool destroyed = false;
  for (int frame = 0; frame < 3; ++frame) {
    VkCommandBuffer cmd = ring.begin();
    if (frame == 0) ctx().deferred().defer(Probe(&destroyed));
    if (frame == 1) {
      EXPECT_FALSE(destroyed) << "destroyed while frame 0 may still be in flight";
    } else if (frame == 2) {
      EXPECT_TRUE(destroyed) << "not destroyed after frame 0's fence";
    }
    vk::dispatch(cmd, saxpy, {vk::bind(0, x), vk::bind(1, y)}, push, vk::groups_for(saxpy, {1024, 1, 1}));
    vk::memory_barrier(cmd, vk::access::kComputeWrite, vk::access::kHostRead);
    ring.submit();
    ring.wait_last();  // frames are serialised here because all three write y
  }
  EXPECT_EQ(ring.frame_number(), 3u);
  y.invalidate();
  // Three frames each added 1 * 1: small integers, exact with or without FMA.
  for (float v : y.mapped_as<float>()) ASSERT_EQ(v, 3.0f);
}

TEST_F(FrameRingTest, MisuseIsReported) {
  vk::FrameRing ring(ctx(), 2);
  EXPECT_THROW(ring.submit(), std::logic_error);
  ring.begin();
  EXPECT_THROW(ring.begin(), std::logic_error);
  ring.submit();
  EXPECT_THROW(vk::FrameRing(ctx(), 9), std::logic_error);
}

}  // namespace
}  // namespace lagoon::test
