// The frame's structure (issue 12): errors from user parameters come back as Result, record() never
// submits, a host's own targets get the same picture, and the ocean's FFT builds only the pipelines it uses.
#include <gtest/gtest.h>

#include "fft/gpu_fft.h"
#include "render/ocean_renderer.h"
#include "scene/scene_io.h"
#include "support/shipped_scene.h"
#include "support/vk_fixture.h"
#include "vk/barriers.h"
#include "vk/transfer.h"

namespace lagoon::test {
namespace {

class FrameStructure : public GpuTest {
 protected:
  scene::Scene load(std::vector<std::string> overrides = {}) {
    overrides.insert(overrides.begin(), {"render.width=96", "render.height=64"});
    return shipped_scene("default", overrides);
  }
};

TEST_F(FrameStructure, InvalidOceanParametersAreAResultNotAnException) {
  scene::Scene s = load();
  s.ocean.cascades.clear();  // what the scene loader would refuse; a host may build Scene by hand
  std::optional<Result<std::unique_ptr<render::OceanRenderer>>> renderer;
  ASSERT_NO_THROW(renderer.emplace(render::OceanRenderer::create(ctx(), s)));
  ASSERT_FALSE(*renderer);
  EXPECT_NE(renderer->error().message.find("ocean"), std::string::npos) << renderer->error().message;
  auto gpu = ocean::GpuOcean::create(ctx(), s.ocean);
  ASSERT_FALSE(gpu);
  EXPECT_NE(gpu.error().message.find("cascades"), std::string::npos) << gpu.error().message;
}

// Before the split, record() ran the foam warm-up with submit_and_wait inside the caller's recording: in
// a caller's own submit_and_wait that nested two submissions on one command pool (a validation error).
TEST_F(FrameStructure, RecordNeverSubmitsAndPrepareWarmsUpOutsideIt) {
  const scene::Scene s = load({"time_s=40"});
  auto renderer = render::OceanRenderer::create(ctx(), s);
  ASSERT_TRUE(renderer) << renderer.error().message;
  const VkExtent2D extent{s.render.width, s.render.height};
  (*renderer)->prepare(s);
  ctx().submit_and_wait([&](VkCommandBuffer cmd) { (*renderer)->record(cmd, s, extent, 0); });
  scene::Scene later = s;
  later.time_s = 500;  // a jump without prepare(): recorded all the same, foam not warmed up
  ctx().submit_and_wait([&](VkCommandBuffer cmd) { (*renderer)->record(cmd, later, extent, 1); });
  EXPECT_FALSE((*renderer)->timings(1).empty());
}

// A dataset frame's ground truth is drawn at the picture's time: the cascades are there already, so its
// frames record no ocean step (a step by dt = 0 made the same textures again, an ocean step each time); a
// ground-truth frame at another time still steps.
TEST_F(FrameStructure, GroundTruthAtThePicturesTimeDoesNotStepTheOceanAgain) {
  const scene::Scene s = load();
  auto renderer = render::OceanRenderer::create(ctx(), s);
  ASSERT_TRUE(renderer) << renderer.error().message;
  const auto ocean_steps = [&] {
    int steps = 0;
    for (const vk::PassTime& t : (*renderer)->timings(0)) steps += t.name.rfind("ocean", 0) == 0;
    return steps;
  };
  std::vector<vk::PassTime> picture;
  (void)(*renderer)->render(s, &picture);
  int picture_steps = 0;
  for (const vk::PassTime& t : picture) picture_steps += t.name.rfind("ocean", 0) == 0;
  EXPECT_GT(picture_steps, 0) << "the picture's own frame steps the ocean";
  (void)(*renderer)->render_surface_aov(s, true);
  EXPECT_EQ(ocean_steps(), 0);
  scene::Scene later = s;
  later.time_s += 0.5f;
  (void)(*renderer)->render_surface_aov(later, true);
  EXPECT_GT(ocean_steps(), 0);
}

TEST_F(FrameStructure, HostTargetsGetTheSamePicture) {
  const scene::Scene s = load();
  auto renderer = render::OceanRenderer::create(ctx(), s);
  ASSERT_TRUE(renderer) << renderer.error().message;
  const io::Image8 own = (*renderer)->render(s);

  const VkExtent2D extent{s.render.width, s.render.height};
  const vk::Image color = vk::Image::create(
      ctx(), {.format = render::OceanRenderer::kColorFormat,
              .extent = extent,
              .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
              .debug_name = "host color"});
  const vk::Image depth = vk::Image::create(ctx(), {.format = render::OceanRenderer::kDepthFormat,
                                                    .extent = extent,
                                                    .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                                    .debug_name = "host depth"});
  (*renderer)->prepare(s);
  ctx().submit_and_wait([&](VkCommandBuffer cmd) {
    (*renderer)->record(cmd, s, {color.handle(), color.view(), depth.handle(), depth.view(), extent}, 0);
  });
  const std::vector<std::byte> host = vk::readback_image(
      ctx(), color, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, vk::access::kColorAttachmentWrite);
  ASSERT_EQ(host.size(), own.rgba.size());
  EXPECT_EQ(0, std::memcmp(host.data(), own.rgba.data(), host.size())) << "the host's image differs";
}

TEST_F(FrameStructure, FusedFftEndsBuildNoPipelinesForThem) {
  const fft::GpuFft2d own(ctx(), 256, true, 4), fused(ctx(), 256, true, 4, fft::GpuFft2d::Ends::Fused);
  EXPECT_EQ(own.pipeline_count(), own.pass_count());
  EXPECT_EQ(fused.pipeline_count(), fused.pass_count() - 2);
}

}  // namespace
}  // namespace lagoon::test
