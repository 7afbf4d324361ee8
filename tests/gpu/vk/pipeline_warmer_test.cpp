// Pipelines made ahead on another thread (vk/pipeline_warmer.h, vk/pipeline_registry.h): the first use takes
// the pipeline the warmer made instead of making another, a making ahead is not a use (only uses are
// remembered for the next run), and owners destroyed while the warmer makes their pipelines are waited for.
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "lagoon_test_shaders/shaders.h"
#include "support/vk_fixture.h"
#include "vk/pipeline.h"
#include "vk/pipeline_warmer.h"

namespace lagoon::test {
namespace {

class PipelineWarmerTest : public GpuTest {
 protected:
  const std::string key_ = "compute " + std::string(shaders::gpu_saxpy_comp.name);

  static VkPipeline made_by_now(vk::PipelineRecipe& recipe) {
    std::lock_guard lock(recipe.mutex);
    return recipe.pipeline;
  }
};

TEST_F(PipelineWarmerTest, TheFirstUseTakesThePipelineMadeAheadAndOnlyUsesAreListed) {
  const vk::ComputePipeline saxpy = vk::ComputePipeline::create(ctx(), shaders::gpu_saxpy_comp);
  const size_t before = ctx().pipelines().used_count();
  const auto recipes = ctx().pipelines().find(std::vector{key_});
  ASSERT_EQ(recipes.size(), 1u) << "the registry holds the live pipeline under " << key_;
  EXPECT_EQ(made_by_now(*recipes[0]), VK_NULL_HANDLE) << "made before its first use";
  vk::PipelineWarmer warmer(recipes);
  warmer.wait();
  const VkPipeline ahead = made_by_now(*recipes[0]);
  EXPECT_NE(ahead, VK_NULL_HANDLE) << "the warmer did not make it";
  EXPECT_EQ(ctx().pipelines().used_count(), before) << "making ahead counted as a use";
  EXPECT_EQ(saxpy.pipeline(), ahead) << "the first use made another pipeline";
  EXPECT_EQ(saxpy.pipeline(), ahead);
  EXPECT_EQ(ctx().pipelines().used_keys(before), std::vector{key_}) << "one use, listed once";
}

TEST_F(PipelineWarmerTest, OwnersGoneWhileTheWarmerMakesTheirPipelinesAreWaitedFor) {
  std::vector<vk::ComputePipeline> gone_before, gone_during;
  for (int i = 0; i < 3; ++i) {
    gone_before.push_back(vk::ComputePipeline::create(ctx(), shaders::gpu_saxpy_comp));
    gone_during.push_back(vk::ComputePipeline::create(ctx(), shaders::gpu_saxpy_comp));
  }
  auto recipes = ctx().pipelines().find(std::vector{key_});
  ASSERT_EQ(recipes.size(), 6u);
  gone_before.clear();  // their recipes stay in the list, with nothing left to make
  vk::PipelineWarmer warmer(recipes);
  // The others go while the warmer makes the first of its list (it works backwards: the last recipe).
  for (int wait = 0; wait < 100000; ++wait) {      // up to 10 s
    if (!recipes.back()->mutex.try_lock()) break;  // being made
    const bool made = recipes.back()->pipeline != VK_NULL_HANDLE;
    recipes.back()->mutex.unlock();
    if (made) break;
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
  gone_during.clear();
  warmer.wait();
  size_t made = 0, made_for_gone_owners = 0;
  for (size_t i = 0; i < recipes.size(); ++i) {
    std::lock_guard lock(recipes[i]->mutex);
    EXPECT_FALSE(recipes[i]->make) << "an owner gone leaves nothing to make";
    made += recipes[i]->pipeline != VK_NULL_HANDLE;
    made_for_gone_owners += i % 2 == 0 && recipes[i]->pipeline != VK_NULL_HANDLE;  // created alternately
  }
  EXPECT_EQ(made_for_gone_owners, 0u) << "the warmer made pipelines whose owners were gone";
  EXPECT_GE(made, 1u) << "the owners went before the warmer began: the case was not tried";
  recipes.clear();  // the last holders: whatever was made is destroyed here, the device still alive
  EXPECT_TRUE(ctx().pipelines().find(std::vector{key_}).empty());
}

}  // namespace
}  // namespace lagoon::test
