// The frame renderer on lavapipe: a golden image with a declared tolerance, and properties that hold
// whatever the golden file says.
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/geometric.hpp>

#include "optics/lut.h"
#include "render/ocean_renderer.h"
#include "scene/scene_io.h"
#include "support/image_compare.h"
#include "support/shipped_scene.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

class OceanRender : public GpuTest {
 protected:
  scene::Scene load(std::vector<std::string> overrides = {}) {
    overrides.insert(overrides.begin(), {"render.width=160", "render.height=90"});
    return shipped_scene("default", overrides);
  }
  io::Image8 render(const scene::Scene& s) {
    auto renderer = render::OceanRenderer::create(ctx(), s);
    EXPECT_TRUE(renderer) << renderer.error().message;
    return (*renderer)->render(s);
  }
};

glm::dvec3 mean_rgb(const io::Image8& img, uint32_t y0, uint32_t y1) {
  glm::dvec3 sum(0);
  for (uint32_t y = y0; y < y1; ++y)
    for (uint32_t x = 0; x < img.width; ++x)
      sum += glm::dvec3(img.pixel(x, y)[0], img.pixel(x, y)[1], img.pixel(x, y)[2]);
  return sum / (double(y1 - y0) * img.width);
}

TEST_F(OceanRender, SkyAboveWaterBelowAndDeterministic) {
  const scene::Scene s = load();
  const io::Image8 a = render(s), b = render(s);
  EXPECT_EQ(a.rgba, b.rgba) << "two renders of the same scene differ";
  const glm::dvec3 sky = mean_rgb(a, 0, 10), water = mean_rgb(a, 80, 90);
  EXPECT_GT(sky.b, sky.r + 10) << "the sky is not blue";
  EXPECT_LT(water.g, sky.g) << "the water is not darker than the sky";
  for (size_t i = 3; i < a.rgba.size(); i += 4) ASSERT_EQ(a.rgba[i], 255);
}

TEST_F(OceanRender, TimeMovesTheWavesButNotTheSky) {
  const io::Image8 t0 = render(load({"time_s=10"})), t1 = render(load({"time_s=12.5"}));
  EXPECT_NEAR(mean_rgb(t0, 0, 10).b, mean_rgb(t1, 0, 10).b, 0.01);
  long changed = 0;
  for (uint32_t y = 50; y < 90; ++y)
    for (uint32_t x = 0; x < t0.width; ++x)
      if (std::abs(t0.pixel(x, y)[2] - t1.pixel(x, y)[2]) > 2) ++changed;
  EXPECT_GT(changed, 160 * 40 / 10) << "the water did not move between t = 10 and t = 12.5 s";
}

TEST_F(OceanRender, ExposureBrightensTheFrame) {
  const io::Image8 dim = render(load({"render.exposure=0.5"})), bright = render(load({"render.exposure=2"}));
  EXPECT_GT(mean_rgb(bright, 0, 90).g, mean_rgb(dim, 0, 90).g + 10);
}

// Looking down into open water, the colour follows the LUT's deep colour of the water type: clear ocean
// blue, turbid coastal water green.
TEST_F(OceanRender, WaterTypeChangesTheDeepColourAsTheLutsSay) {
  const std::vector<std::string> down{"camera.position=[0,12,0]", "camera.look_at=[0,0,3]",
                                      "ocean.spectrum.wind_speed_mps=3"};
  auto with = [&](const char* type) {
    auto o = down;
    o.push_back(std::string("water.type=") + type);
    return mean_rgb(render(load(o)), 30, 60);
  };
  const glm::dvec3 clear = with("jerlov-I"), turbid = with("jerlov-9C");
  EXPECT_GT(clear.b, clear.g);
  EXPECT_GT(turbid.g / turbid.b, clear.g / clear.b + 0.1) << "9C should be greener than I";
  // The same ordering as the LUTs' deep colours themselves.
  auto deep = [](const char* type) {
    optics::WaterParams w;
    w.type = type;
    w.lut_size = 2;
    auto in = optics::lut_inputs(w, 30.0);
    return optics::build_water_lut(*in)->deep_colour;
  };
  EXPECT_GT(deep("jerlov-9C").g / deep("jerlov-9C").b, deep("jerlov-I").g / deep("jerlov-I").b);
}

}  // namespace
}  // namespace lagoon::test

namespace lagoon::test {
namespace {

// Standard deviation over the centre of the image of the luminance difference between two renders of the
// same sea: with and without the floor's texture, it is how much of the texture shows through the water.
// The waves' own glitter is the same in both and cancels, so the measure holds whatever the device resolves.
double centre_contrast(const io::Image8& textured, const io::Image8& plain) {
  double sum = 0, sum2 = 0;
  int n = 0;
  auto luminance = [](const uint8_t* p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; };
  for (uint32_t y = textured.height / 4; y < 3 * textured.height / 4; ++y)
    for (uint32_t x = textured.width / 4; x < 3 * textured.width / 4; ++x) {
      const double l = luminance(textured.pixel(x, y)) - luminance(plain.pixel(x, y));
      sum += l, sum2 += l * l, ++n;
    }
  return std::sqrt(std::max(sum2 / n - (sum / n) * (sum / n), 0.0));
}

class BayRender : public OceanRender {
 protected:
  // Looking straight down from 6 m onto a flat sandy floor `depth` metres under calm, clear water. Without
  // caustics: they modulate the light on the floor, which is not what these tests measure.
  io::Image8 looking_down(double depth, const char* water = "jerlov-IB", bool textured = true) {
    return render(load(
        {"camera.position=[0,6,0]", "camera.look_at=[0,0,0.001]", "ocean.spectrum.wind_speed_mps=2",
         "render.exposure=1", "seafloor.type=slope", "seafloor.depth_near_m=" + std::to_string(depth),
         "seafloor.depth_far_m=" + std::to_string(depth),
         textured ? "seafloor.texture=assets/sand.png" : "seafloor.texture=", "seafloor.albedo=[1,1,1]",
         "seafloor.texture_scale_m=1", "render.effects.caustics=false", std::string("water.type=") + water}));
  }
  double floor_contrast(double depth) {
    return centre_contrast(looking_down(depth), looking_down(depth, "jerlov-IB", false));
  }
};

TEST_F(BayRender, ShallowWaterShowsTheFloorDeepWaterHidesIt) {
  const io::Image8 shallow = looking_down(1.0), deep = looking_down(25.0);
  const glm::dvec3 s = mean_rgb(shallow, 30, 60), d = mean_rgb(deep, 30, 60);
  // Over 1 m of clear water the sand (beige, R > B) is seen; over 25 m the water's own blue.
  EXPECT_GT(s.r, d.r + 20) << "the sand's red does not show through shallow water";
  EXPECT_GT(d.b, d.r) << "deep water is not blue";
}

TEST_F(BayRender, FloorTextureContrastFallsWithDepth) {
  const double c1 = floor_contrast(0.6), c4 = floor_contrast(4.0), c15 = floor_contrast(15.0);
  std::printf("floor texture contrast: %.2f at 0.6 m, %.2f at 4 m, %.2f at 15 m\n", c1, c4, c15);
  EXPECT_GT(c1, c4) << "contrast at 0.6 m " << c1 << ", at 4 m " << c4;
  EXPECT_GT(c4, c15) << "contrast at 4 m " << c4 << ", at 15 m " << c15;
}

TEST_F(BayRender, MissingFloorTextureIsAnErrorNamingIt) {
  auto s = load({"seafloor.type=slope", "seafloor.texture=assets/no-such-sand.png"});
  auto renderer = render::OceanRenderer::create(ctx(), s);
  ASSERT_FALSE(renderer);
  EXPECT_NE(renderer.error().message.find("no-such-sand.png"), std::string::npos) << renderer.error().message;
}

}  // namespace
}  // namespace lagoon::test

namespace lagoon::test {
namespace {

class ShippedScenes : public GpuTest, public ::testing::WithParamInterface<const char*> {};

// Each shipped scene at 320x180 against its golden image, which lavapipe renders (make update-golden). On
// lavapipe the tolerance guards against regressions; on any other device it is the cross-device agreement
// Lagoon promises (docs/devices.md): PSNR >= 35 dB and at most 1 % of pixels more than 8/255 apart.
TEST_P(ShippedScenes, MatchGolden) {
  const std::string name = GetParam();
  auto s = scene::load_scene(std::string(LAGOON_SOURCE_DIR) + "/scenes/" + name + ".json",
                             std::vector<std::string>{"render.width=320", "render.height=180"});
  ASSERT_TRUE(s) << s.error().message;
  auto renderer = render::OceanRenderer::create(ctx(), *s);
  ASSERT_TRUE(renderer) << renderer.error().message;
  const io::Image8 image = (*renderer)->render(*s);
  const bool golden_device = ctx().properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  const CompareOptions tolerance =
      golden_device
          ? CompareOptions{.channel_tolerance = 3, .max_differing_fraction = 0.01, .min_psnr_db = 40.0}
          : io::kDeviceAgreement;
  EXPECT_TRUE(matches_golden(image, std::string(LAGOON_SOURCE_DIR) + "/tests/golden/" + name + "_320x180.png",
                             tolerance, std::string(LAGOON_TEST_ARTIFACTS) + "/render"));
}

INSTANTIATE_TEST_SUITE_P(Scenes, ShippedScenes,
                         ::testing::Values("default", "open-ocean", "tropical-lagoon", "reef-dive",
                                           "waterline", "harbour", "beach"),
                         [](const auto& info) {
                           std::string n = info.param;
                           std::replace(n.begin(), n.end(), '-', '_');
                           return n;
                         });

class ReflectionRender : public OceanRender {};

// A red buoy above calm water: with the reflection on, red appears in the water below it.
TEST_F(ReflectionRender, ObjectAboveTheWaterAppearsMirrored) {
  const std::vector<std::string> base{"camera.position=[0,1.5,-10]",
                                      "camera.look_at=[0,0.5,0]",
                                      "ocean.spectrum.wind_speed_mps=1",
                                      "objects=[{\"file\":\"assets/buoy.gltf\"}]",
                                      "render.width=160",
                                      "render.height=90"};
  auto with = [&](bool reflection) {
    auto o = base;
    o.push_back(std::string("render.effects.reflection=") + (reflection ? "true" : "false"));
    return render(load(o));
  };
  const io::Image8 on = with(true), off = with(false);
  // Find the buoy's rows (strongly red pixels) in the upper half, then look below the horizon line.
  auto redness = [](const io::Image8& img, uint32_t y0, uint32_t y1) {
    double red = 0;
    for (uint32_t y = y0; y < y1; ++y)
      for (uint32_t x = 60; x < 100; ++x)
        red += std::max(0, int(img.pixel(x, y)[0]) - int(img.pixel(x, y)[2]));
    return red;
  };
  EXPECT_GT(redness(on, 0, 45), 1000) << "the buoy itself is not visible";
  EXPECT_GT(redness(on, 48, 90), redness(off, 48, 90) + 500) << "no mirrored red below the buoy";
}

// At grazing angles the water reflects almost everything: just below the horizon it nearly equals the sky
// just above it, while looking steeply down it does not.
TEST_F(ReflectionRender, GrazingViewTendsToTheSky) {
  const io::Image8 img =
      render(load({"camera.position=[0,2,0]", "camera.look_at=[0,2,100]", "ocean.spectrum.wind_speed_mps=2",
                   "render.width=160", "render.height=90"}));
  const glm::dvec3 sky = mean_rgb(img, 40, 44), water_far = mean_rgb(img, 46, 48),
                   water_near = mean_rgb(img, 85, 90);
  EXPECT_LT(glm::length(water_far - sky), 0.5 * glm::length(water_near - sky))
      << "far water " << water_far.b << " sky " << sky.b << " near water " << water_near.b;
}

}  // namespace
}  // namespace lagoon::test

namespace lagoon::test {
namespace {

class LightRender : public OceanRender {};

// At night a point light above the water makes a highlight on it; without it the water stays dark.
TEST_F(LightRender, PointLightLightsTheWaterAtNight) {
  const std::vector<std::string> night{"sun.elevation_deg=-8",    "render.exposure=6",
                                       "seafloor.type=none",      "objects=[]",
                                       "camera.position=[0,4,0]", "camera.look_at=[0,0,30]"};
  auto with = [&](bool lamp) {
    auto o = night;
    o.push_back(lamp ? R"(lights=[{"position":[0,4,25],"colour":[1,0.8,0.5],"intensity":40,"range_m":80}])"
                     : "lights=[]");
    return render(load(o));
  };
  const io::Image8 dark = with(false), lit = with(true);
  int brightest_dark = 0, brightest_lit = 0;
  for (uint32_t y = 50; y < 90; ++y)
    for (uint32_t x = 0; x < 160; ++x) {
      brightest_dark = std::max(brightest_dark, int(dark.pixel(x, y)[0]));
      brightest_lit = std::max(brightest_lit, int(lit.pixel(x, y)[0]));
    }
  EXPECT_GT(brightest_lit, brightest_dark + 60) << "no highlight from the point light";
}

}  // namespace
}  // namespace lagoon::test
