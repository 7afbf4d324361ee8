// The context's promises: validation failures are caught, timestamps time passes, the pipeline cache
// persists and a foreign cache file is ignored, deferred destruction waits for its frame.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lagoon_test_shaders/shaders.h"
#include "support/vk_fixture.h"
#include "vk/barriers.h"
#include "vk/check.h"
#include "vk/gpu_timer.h"
#include "vk/pipeline.h"
#include "vk/pipeline_cache.h"

namespace lagoon::test {
namespace {

class ContextTest : public GpuTest {};

std::filesystem::path temp_dir(const std::string& name) {
  auto dir = std::filesystem::path(LAGOON_TEST_ARTIFACTS) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// Proves that a test can fail on validation: an invalid call must be counted.
TEST(ValidationLayer, CountsAnInvalidCall) {
  vk::ContextOptions options = vk::ContextOptions::from_environment();
  options.validation = true;
  options.pipeline_cache_dir.clear();
  auto ctx = vk::Context::create(options);
  ASSERT_TRUE(ctx) << ctx.error().message;
  (*ctx)->validation().set_echo(false);
  ASSERT_EQ((*ctx)->validation().failures(), 0u);
  // VUID-VkBufferCreateInfo-size-00912: size must be greater than 0.
  const VkBufferCreateInfo info{
      .sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO, .size = 0, .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT};
  VkBuffer buffer = VK_NULL_HANDLE;
  vkCreateBuffer((*ctx)->device(), &info, nullptr, &buffer);
  if (buffer != VK_NULL_HANDLE) vkDestroyBuffer((*ctx)->device(), buffer, nullptr);
  EXPECT_GE((*ctx)->validation().failures(), 1u);
  ASSERT_FALSE((*ctx)->validation().messages().empty());
  EXPECT_NE((*ctx)->validation().messages()[0].find("size"), std::string::npos);
}

TEST_F(ContextTest, ReportsTheChosenDevice) {
  const vk::DeviceInfo& info = ctx().device_info();
  EXPECT_FALSE(info.name.empty());
  EXPECT_GE(info.api_version, VK_API_VERSION_1_3);
  EXPECT_TRUE(ctx().validation_enabled());
}

TEST_F(ContextTest, TimestampsTimeEachScope) {
  vk::GpuTimer timer(ctx());
  if (!timer.supported()) GTEST_SKIP() << "device has no timestamps";
  const vk::ComputePipeline saxpy = vk::ComputePipeline::create(ctx(), shaders::gpu_saxpy_comp);
  const uint32_t n = 1 << 20;
  vk::Buffer b =
      vk::Buffer::create(ctx(), n * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUsage::Device);
  struct Push {
    float a;
    uint32_t n;
  } push{1.0f, n};
  ctx().submit_and_wait([&](VkCommandBuffer cmd) {
    timer.reset(cmd);
    { vk::GpuScope s(timer, cmd, "empty"); }
    {
      vk::GpuScope s(timer, cmd, "saxpy");
      for (int i = 0; i < 8; ++i) {
        vk::dispatch(cmd, saxpy, {vk::bind(0, b), vk::bind(1, b)}, push, vk::groups_for(saxpy, {n, 1, 1}));
        vk::memory_barrier(cmd, vk::access::kComputeReadWrite, vk::access::kComputeReadWrite);
      }
    }
  });
  const auto times = timer.results();
  ASSERT_EQ(times.size(), 2u);
  EXPECT_EQ(times[0].name, "empty");
  EXPECT_EQ(times[1].name, "saxpy");
  EXPECT_GE(times[0].ms, 0.0);
  EXPECT_GT(times[1].ms, times[0].ms);  // 8 passes over 4 MiB cannot take less time than nothing
  EXPECT_LT(times[1].ms, 60'000.0);     // a wrapped or unscaled counter would give absurd values
}

TEST_F(ContextTest, PipelineCachePersistsAndForeignFilesAreIgnored) {
  // Not "pipeline-cache": test_main points every test process's LAGOON_PIPELINE_CACHE there, so under
  // ctest -j other tests write into it while this one expects to be its only writer.
  const auto dir = temp_dir("pipeline-cache-persist-test");
  vk::ContextOptions options = vk::ContextOptions::from_environment();
  options.validation = true;
  options.pipeline_cache_dir = dir;
  std::filesystem::path file;
  {
    auto c = vk::Context::create(options);
    ASSERT_TRUE(c) << c.error().message;
    file = (*c)->pipeline_cache_file();
    EXPECT_EQ(file.parent_path(), dir);
    vk::ComputePipeline p = vk::ComputePipeline::create(**c, shaders::gpu_saxpy_comp);
  }  // destruction writes the cache
  ASSERT_TRUE(std::filesystem::exists(file));
  EXPECT_GE(std::filesystem::file_size(file), sizeof(VkPipelineCacheHeaderVersionOne));
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(entry.path(), file) << "temporary file left behind";

  // A file of garbage under the expected name must not be passed to the driver or break start-up.
  { std::ofstream(file, std::ios::binary | std::ios::trunc) << "not a pipeline cache"; }
  auto c = vk::Context::create(options);
  ASSERT_TRUE(c) << c.error().message;
  EXPECT_EQ((*c)->validation().failures(), 0u);
}

TEST_F(ContextTest, DeferredDestructionWaitsForItsFrameSlot) {
  vk::DeferredDestroyer deferred(2);
  deferred.begin_frame(0);
  deferred.defer(vk::Buffer::create(ctx(), 256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUsage::Upload));
  EXPECT_EQ(deferred.pending(), 1u);
  deferred.begin_frame(1);  // the other frame in flight: frame 0's fence has not been waited on yet
  EXPECT_EQ(deferred.pending(), 1u);
  deferred.begin_frame(0);  // frame 0 came round again: its objects go
  EXPECT_EQ(deferred.pending(), 0u);
}

TEST_F(ContextTest, VkCheckNamesTheCallAndResult) {
  try {
    VK_CHECK(VK_ERROR_DEVICE_LOST);
    FAIL() << "VK_CHECK did not throw";
  } catch (const vk::VulkanError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("VK_ERROR_DEVICE_LOST"), std::string::npos) << what;
    EXPECT_NE(what.find("context_test.cpp"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace lagoon::test
