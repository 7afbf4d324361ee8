// The foundation's headless render: a golden image with a declared tolerance, plus properties that hold
// whatever the golden file says.
#include <gtest/gtest.h>

#include "render/placeholder_renderer.h"
#include "support/image_compare.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

class PlaceholderRender : public GpuTest {
 protected:
  scene::Scene load(std::vector<std::string> overrides = {}) {
    overrides.push_back("render.width=160");
    overrides.push_back("render.height=90");
    auto s = scene::load_scene(std::string(LAGOON_SOURCE_DIR) + "/scenes/default.json", overrides);
    EXPECT_TRUE(s) << s.error().message;
    return *s;
  }
  io::Image8 render(const scene::Scene& s) {
    render::PlaceholderRenderer renderer(ctx());
    return renderer.render(s);
  }
};

double mean_channel(const io::Image8& img, int channel, uint32_t y0, uint32_t y1) {
  double sum = 0;
  for (uint32_t y = y0; y < y1; ++y)
    for (uint32_t x = 0; x < img.width; ++x) sum += img.pixel(x, y)[channel];
  return sum / (double(y1 - y0) * img.width);
}

TEST_F(PlaceholderRender, DefaultSceneMatchesGolden) {
  const io::Image8 image = render(load());
  // lavapipe is deterministic for a given Mesa build; the tolerance absorbs other LLVM/Mesa versions.
  const CompareOptions tolerance{
      .channel_tolerance = 3, .max_differing_fraction = 0.005, .min_psnr_db = 35.0};
  EXPECT_TRUE(matches_golden(image,
                             std::string(LAGOON_SOURCE_DIR) + "/tests/golden/placeholder_default_160x90.png",
                             tolerance, std::string(LAGOON_TEST_ARTIFACTS) + "/render"));
}

TEST_F(PlaceholderRender, SkyAboveWaterBelowAndDeterministic) {
  const scene::Scene s = load();
  const io::Image8 a = render(s), b = render(s);
  ASSERT_EQ(a.width, 160u);
  ASSERT_EQ(a.height, 90u);
  EXPECT_EQ(a.rgba, b.rgba) << "two renders of the same scene differ";
  // Top rows: daylight sky, blue dominant and bright. Bottom rows: water, darker than the sky.
  const double sky_b = mean_channel(a, 2, 0, 10), sky_r = mean_channel(a, 0, 0, 10);
  const double water_b = mean_channel(a, 2, 80, 90);
  EXPECT_GT(sky_b, sky_r + 20) << "sky is not blue";
  EXPECT_GT(sky_b, 120);
  EXPECT_LT(water_b, sky_b) << "water is not darker than the sky";
  for (size_t i = 3; i < a.rgba.size(); i += 4) ASSERT_EQ(a.rgba[i], 255);
}

TEST_F(PlaceholderRender, TimeMovesTheWavesButNotTheSky) {
  const io::Image8 t0 = render(load({"time_s=0"})), t1 = render(load({"time_s=2.5"}));
  EXPECT_NEAR(mean_channel(t0, 2, 0, 10), mean_channel(t1, 2, 0, 10), 0.01);
  long changed = 0;
  for (uint32_t y = 60; y < 90; ++y)
    for (uint32_t x = 0; x < t0.width; ++x)
      if (std::abs(t0.pixel(x, y)[2] - t1.pixel(x, y)[2]) > 2) ++changed;
  EXPECT_GT(changed, 160 * 30 / 10) << "the water did not move between t = 0 and t = 2.5 s";
}

TEST_F(PlaceholderRender, ExposureBrightensTheFrame) {
  const io::Image8 dim = render(load({"render.exposure=0.5"})), bright = render(load({"render.exposure=2"}));
  EXPECT_GT(mean_channel(bright, 1, 0, 90), mean_channel(dim, 1, 0, 90) + 10);
}

}  // namespace
}  // namespace lagoon::test
