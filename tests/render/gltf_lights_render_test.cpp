// KHR_lights_punctual in the frame (issue 17, item 1): an object's glTF lamp lights the water exactly as the
// same lamp written into the scene's lights does, once its candela are put in white units, and
// objects[].lights_from_gltf = false switches it off.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "render/ocean_renderer.h"
#include "render/sky_light.h"
#include "support/image_compare.h"
#include "support/temp_dir.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

using nlohmann::json;

int max_channel_difference(const io::Image8& a, const io::Image8& b) {
  return compare_images(a, b, {}).max_channel_difference;
}

constexpr double kCandela = 4.0e6;  // a bright lamp: the scene light below is then intensity ~40 at night

class GltfLightsRender : public GpuTest {
 protected:
  TempDir dir_{"lagoon_gltf_lights_render"};

  void SetUp() override {
    GpuTest::SetUp();
    // A model with no geometry, only a lamp 1 m above its origin.
    const json lamp = {
        {"asset", {{"version", "2.0"}}},
        {"extensionsUsed", {"KHR_lights_punctual"}},
        {"extensions",
         {{"KHR_lights_punctual",
           {{"lights", json::array({json{{"type", "point"},
                                         {"color", {1.0, 0.8, 0.5}},
                                         {"intensity", kCandela},
                                         {"range", 80.0}}})}}}}},
        {"scene", 0},
        {"scenes", json::array({json{{"nodes", {0}}}})},
        {"nodes", json::array({json{{"translation", {0, 1, 0}},
                                    {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}})}};
    std::ofstream(dir_ / "lamp.gltf") << lamp.dump();
  }

  scene::Scene night(const json& objects, const json& lights) {
    std::ifstream in(std::string(LAGOON_SOURCE_DIR) + "/scenes/default.json");
    json s = json::parse(in);
    s["sun"]["elevation_deg"] = -8;
    s["render"]["exposure"] = 6;
    s["render"]["width"] = 160;
    s["render"]["height"] = 90;
    s["seafloor"] = {{"type", "none"}};
    s["camera"] = {{"position", {0, 4, 0}}, {"look_at", {0, 0, 30}}};
    s["objects"] = objects;
    s["lights"] = lights;
    std::ofstream(dir_ / "night.json") << s.dump();
    auto scene = scene::load_scene(dir_ / "night.json");
    EXPECT_TRUE(scene) << scene.error().message;
    return *scene;
  }

  io::Image8 render(const scene::Scene& s) {
    auto renderer = render::OceanRenderer::create(ctx(), s);
    EXPECT_TRUE(renderer) << renderer.error().message;
    return (*renderer)->render(s);
  }
};

int brightest_red(const io::Image8& img) {
  int best = 0;
  for (uint32_t y = 50; y < 90; ++y)
    for (uint32_t x = 0; x < img.width; ++x) best = std::max(best, int(img.pixel(x, y)[0]));
  return best;
}

TEST_F(GltfLightsRender, AnObjectsLampIsTheSceneLampItStandsFor) {
  const json object = {{"file", "lamp.gltf"}, {"position", {0, 3, 25}}};
  const scene::Scene with_gltf = night(json::array({object}), json::array());
  const double intensity = kCandela / render::reference_illuminance_lux(with_gltf.sun);
  const scene::Scene written = night(
      json::array(),
      json::array({json{
          {"position", {0, 4, 25}}, {"colour", {1, 0.8, 0.5}}, {"intensity", intensity}, {"range_m", 80}}}));
  const io::Image8 a = render(with_gltf), b = render(written);
  EXPECT_LE(max_channel_difference(a, b), 1);
  json off = object;
  off["lights_from_gltf"] = false;
  const io::Image8 dark = render(night(json::array({off}), json::array()));
  EXPECT_GT(brightest_red(a), brightest_red(dark) + 60) << "the glTF lamp does not light the water";
}

TEST(ReferenceIlluminance, IsDaylightsOrder) {
  // A clear sky with the sun 60° up gives 80-130 klx on a horizontal surface (the optics model's 380-780 nm
  // band holds nearly all of the light the eye sees).
  const double lux = render::reference_illuminance_lux({.elevation_deg = 60.0f});
  EXPECT_GT(lux, 80e3);
  EXPECT_LT(lux, 130e3);
  EXPECT_LT(render::reference_illuminance_lux({.elevation_deg = 10.0f}), 0.4 * lux);
}

}  // namespace
}  // namespace lagoon::test
